#!/usr/bin/env python3
"""Pressure against density of scenes/snow_compression.toml over the data snow_cam_clay was
calibrated on (issue 16, item 3).

usage: compare_compression.py RUN_DIR [--plot FILE.png]

Per output frame: the piston's pressure (piston_fy over the column's 40 x 40 mm cross-section,
metrics.csv) and the snow's plastic density rho0 / mean(J_P) (the particle files' Jp column; all
particles have the same rest volume). The plastic density is what the snow keeps when the load
is gone, the final density CRREL Report 95-7 measured in ruts (crrel_95_7_final_density.csv).
Prints, for each step of that rule the run reached, the simulated density at the step's pressure
(linear interpolation in ln p) against the step's mid density, then `largest_pressure P` and
`largest_density_error_vs_law X`: the largest relative deviation of the simulated density from
the fitted law (fit_cam_clay.py) at the same pressure, once the piston has met the snow. Writes
compression.csv in RUN_DIR and, with --plot, a gnuplot PNG.
"""
import csv
import math
import os
import re
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import fit_cam_clay  # noqa: E402

AREA = 0.040 * 0.040  # m^2, the column's cross-section


def vtp_array(path, name):
    """A Float32 point-data array of a firn .vtp file (raw appended data, UInt64 block sizes)."""
    with open(path, "rb") as f:
        data = f.read()
    m = re.search(rb'<DataArray type="Float32" Name="' + name.encode() + rb'"[^>]*offset="(\d+)"', data)
    if not m:
        raise SystemExit(f"{path}: no Float32 array {name}")
    start = data.index(b'<AppendedData encoding="raw">') + len(b'<AppendedData encoding="raw">')
    start = data.index(b"_", start) + 1 + int(m.group(1))
    (size,) = struct.unpack_from("<Q", data, start)
    return struct.unpack_from(f"<{size // 4}f", data, start + 8)


def main():
    run = sys.argv[1]
    plot = sys.argv[sys.argv.index("--plot") + 1] if "--plot" in sys.argv else None
    scene = open(os.path.join(run, "scene.resolved.toml")).read()
    rho0 = float(re.search(r"^\s*density\s*=\s*([-+0-9.e]+)", scene, re.M).group(1))
    curve = []
    for row in csv.DictReader(open(os.path.join(run, "metrics.csv"))):
        pressure = float(row["piston_fy"]) / AREA
        if pressure <= 0:
            continue
        Jp = vtp_array(os.path.join(run, "particles", f"{int(row['frame']):05d}.vtp"), "Jp")
        curve.append((rho0 * len(Jp) / sum(Jp), pressure))
    with open(os.path.join(run, "compression.csv"), "w") as f:
        f.write("plastic_density,pressure\n")
        for rho, p in curve:
            f.write(f"{rho:.6g},{p:.6g}\n")

    A, rho_h, points = fit_cam_clay.fit_compaction()
    # The scene against the law it was calibrated with: at every frame past twice the rest
    # density's p0 (after the piston's first contact), the density the law gives at the frame's
    # pressure.
    onset = 2 * A * math.exp(rho0 / rho_h)
    worst = 0.0
    for rho, p in curve:
        if p >= onset:
            worst = max(worst, abs(rho / (rho_h * math.log(p / A)) - 1))
    # And against the data where the run reached them: the simulated density at each step's
    # pressure (linear in ln p between frames) against the step's mid density.
    for rho_rule, p in points:
        pairs = [(a, b) for a, b in zip(curve, curve[1:]) if a[1] <= p <= b[1]]
        if not pairs:
            print(f"step {p / 1e3:.0f} kPa: not reached (largest pressure {max(q for _, q in curve) / 1e3:.0f} kPa)")
            continue
        (r0, p0), (r1, p1) = pairs[0]
        rho = r0 + (r1 - r0) * math.log(p / p0) / math.log(p1 / p0)
        print(f"step {p / 1e3:.0f} kPa: simulated {rho:.1f} kg/m^3, rule {rho_rule:.0f} ({100 * (rho / rho_rule - 1):+.1f}%),"
              f" fitted law {rho_h * math.log(p / A):.1f}")
    print(f"largest_pressure {max(p for _, p in curve):.6g}")
    print(f"largest_density_error_vs_law {worst:.4f}")
    if plot:
        law = os.path.join(run, "compression_law.csv")
        with open(law, "w") as f:
            for i in range(101):
                rho = rho0 + (700 - rho0) * i / 100
                f.write(f"{rho},{A * math.exp(rho / rho_h) / 1e3}\n")
        rule = os.path.join(run, "compression_rule.csv")
        with open(rule, "w") as f:
            for rho, p in points:
                f.write(f"{rho},{p / 1e3}\n")
        script = f"""set terminal pngcairo size 800,560 noenhanced
set output '{plot}'
set datafile separator ','
set logscale y
set xlabel 'plastic density (kg/m^3)'
set ylabel 'pressure (kPa)'
set key top left
set title 'snow_compression: fresh_snow under a piston'
plot '{os.path.join(run, "compression.csv")}' every ::1 using 1:($2/1000) with linespoints title 'firn (piston pressure)', \\
     '{law}' using 1:2 with lines dashtype 2 title 'fitted law p0(rho)', \\
     '{rule}' using 1:2 with points pt 7 ps 1.5 title 'CRREL 95-7 rule (step mid densities)'
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
