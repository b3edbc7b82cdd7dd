#!/usr/bin/env python3
"""Pressure against sinkage of scenes/snow_plate_sinkage.toml over the Bekker curve of snow
(issue 16, item 3).

usage: compare_plate_sinkage.py RUN_DIR [--plot FILE.png]

Per output frame: the plate's pressure, plate_fy (metrics.csv) over the strip's loaded area (the
plate's 100 mm width times the snow slice's 16 mm thickness), against its sinkage 0.2 m/s * t (the
plate starts on the snow surface). The Bekker curve p = (k_c / b + k_phi) z^n uses Wong, Theory of
Ground Vehicles, Table 2.3, for snow: n = 1.6, k_c = 4.37 kN/m^(n+1), k_phi = 196.72 kN/m^(n+2),
b = 0.1 m. Prints the two at every 10 mm of sinkage and the ratio; writes plate_sinkage.csv in
RUN_DIR and, with --plot, a gnuplot PNG. The snow is calibrated on laboratory data, not on this
curve: the comparison is a prediction.
"""
import csv
import os
import subprocess
import sys

WIDTH, THICKNESS, SPEED = 0.100, 0.016, 0.2  # m, m, m/s (scenes/snow_plate_sinkage.toml)
N, K_C, K_PHI = 1.6, 4.37e3, 196.72e3  # Wong, Table 2.3, snow


def bekker(z):
    return (K_C / WIDTH + K_PHI) * z ** N


def main():
    run = sys.argv[1]
    plot = sys.argv[sys.argv.index("--plot") + 1] if "--plot" in sys.argv else None
    curve = [(SPEED * float(r["time"]), float(r["plate_fy"]) / (WIDTH * THICKNESS))
             for r in csv.DictReader(open(os.path.join(run, "metrics.csv")))]
    table = os.path.join(run, "plate_sinkage.csv")
    with open(table, "w") as f:
        f.write("sinkage_m,pressure_Pa,bekker_Pa\n")
        for z, p in curve:
            f.write(f"{z:.6g},{p:.6g},{bekker(z):.6g}\n")
    for mm in range(10, 60, 10):
        z = mm / 1000
        near = min(curve, key=lambda c: abs(c[0] - z))
        if abs(near[0] - z) > 1e-3:
            print(f"sinkage {mm} mm: not reached")
            continue
        print(f"sinkage {mm} mm: firn {near[1] / 1e3:.2f} kPa, Bekker {bekker(z) / 1e3:.2f} kPa"
              f" (firn / Bekker {near[1] / bekker(z):.2f})")
    if plot:
        script = f"""set terminal pngcairo size 800,560 noenhanced
set output '{plot}'
set datafile separator ','
set xlabel 'sinkage (mm)'
set ylabel 'pressure (kPa)'
set key top left
set title 'snow_plate_sinkage: a 100 mm strip plate in fresh_snow'
plot '{table}' every ::1 using ($1*1000):($2/1000) with linespoints title 'firn (plate pressure)', \\
     '{table}' every ::1 using ($1*1000):($3/1000) with lines dashtype 2 title 'Bekker, Wong Table 2.3 (snow)'
"""
        subprocess.run(["gnuplot"], input=script, text=True, check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
