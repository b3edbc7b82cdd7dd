#!/usr/bin/env python3
"""The Cam-clay snow calibration (issue 16): the catalog's presets are what the fitting script
data/snow/fit_cam_clay.py computes from the laboratory data in data/snow/, so the two cannot drift.

usage: snow_calibration_test.py FIRN SOURCE_DIR WORK_DIR CHECK   (CHECK: presets)
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


def main():
    firn, source, _work, check = sys.argv[1:5]
    error = {"presets": check_presets}[check](firn, source)
    if error:
        print("FAIL:", error)
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
