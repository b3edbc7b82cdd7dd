#!/usr/bin/env python3
"""The Cam-clay snow calibration (issue 16): the catalog's presets are what the fitting script
data/snow/fit_cam_clay.py computes from the laboratory data in data/snow/, so the two cannot drift.

usage: snow_calibration_test.py FIRN SOURCE_DIR WORK_DIR CHECK   (CHECK: presets, compression)

compression: scenes/snow_compression.toml with one particle per cell (2,500 particles) follows the
fitted compaction law: data/snow/compare_compression.py's largest density deviation from the law
at the piston's pressure within 0.05 (measured 0.027; the full scene, 20,000 particles: see
docs/snow.md). A pressure measured in Kirchhoff instead of Cauchy stress, or p0 off by a factor 2,
moves the density by hardening_density ln 2 = 58 kg/m^3, 13% at 450 kg/m^3.
"""
import re
import subprocess
import sys


def fitted_presets(source):
    out = subprocess.run([sys.executable, f"{source}/data/snow/fit_cam_clay.py"], check=True, capture_output=True,
                         text=True).stdout
    presets = {}
    for line in out.splitlines():
        m = re.match(r"^(\w+): (\{.*\})$", line)
        if m:
            presets[m.group(1)] = {k: float(v) for k, v in re.findall(r'\{"(\w+)", ([-+0-9.e]+)\}', m.group(2))}
    return presets


def catalog_presets(firn):
    out = subprocess.run([firn, "help", "scene-keys"], check=True, capture_output=True, text=True).stdout
    presets = {}
    for line in out.splitlines():
        m = re.match(r"^\| `(\w+)` \| snow_cam_clay \| (.*?) \|", line)
        if m:
            presets[m.group(1)] = {k: float(v) for k, v in re.findall(r"(\w+) = ([-+0-9.e]+)", m.group(2))}
    return presets


def check_presets(firn, source):
    fitted, catalog = fitted_presets(source), catalog_presets(firn)
    if not fitted:
        return "the fitting script printed no preset"
    for name, values in fitted.items():
        if name not in catalog:
            return f"preset {name} is not in the catalog"
        for key, value in values.items():
            have = catalog[name].get(key)
            if have is None or abs(have - value) > 5e-4 * abs(value):
                return f"{name}.{key}: catalog {have}, fit {value}"
    return None


def check_compression(firn, source, work):
    out = f"{work}/compression"
    subprocess.run([firn, "run", f"{source}/scenes/snow_compression.toml", "--out", out, "--set",
                    "simulation.particles_per_cell=1"], check=True, capture_output=True)
    report = subprocess.run([sys.executable, f"{source}/data/snow/compare_compression.py", out], check=True,
                            capture_output=True, text=True).stdout
    print(report)
    error = float(re.search(r"largest_density_error_vs_law ([0-9.e+-]+)", report).group(1))
    if not error < 0.05:
        return f"density deviates from the fitted law by {error:.3f}"
    if not float(re.search(r"largest_pressure ([0-9.e+-]+)", report).group(1)) > 100e3:
        return "the piston never reached 100 kPa"
    return None


def main():
    firn, source, work, check = sys.argv[1:5]
    error = {"presets": lambda: check_presets(firn, source),
             "compression": lambda: check_compression(firn, source, work)}[check]()
    if error:
        print("FAIL:", error)
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
