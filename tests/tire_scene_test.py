"""End-to-end checks of the tire experiment (issue 5): scenes/tire_on_snow.toml at preview
resolution, for each tread and for a loaded axle, and a small `firn sweep` of it.

Usage: python3 tire_scene_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
"""
import csv
import json
import math
import os
import shutil
import subprocess

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh
SCENE = os.path.join(ROOT, "scenes", "tire_on_snow.toml")
TIRE_COLUMNS = ["traction", "vertical_load", "axle_torque", "slip_ratio", "axle_height", "peak_pressure",
                "displaced", "accumulated", "injected", "removed", "tire_fx", "ground_fy"]




def preview_run(name, *sets):
    out = fresh(name)
    args = [FIRN, "run", SCENE, "--preview", "--out", out, "--set", "simulation.end_time=10 ms"]
    for s in sets:
        args += ["--set", s]
    r = subprocess.run(args, capture_output=True, text=True)
    check(r.returncode == 0, f"firn run {' '.join(sets)} exited {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        check(json.load(f)["status"] == "ok", "status not ok")
    with open(os.path.join(out, "metrics.csv")) as f:
        rows = list(csv.DictReader(f))
    return out, rows


def test_treads():
    for tread in ["angled_footstep", "bowtie", "six_rib"]:
        out, rows = preview_run("tread_" + tread, "tire.tread=" + tread)
        last = rows[-1]
        for c in TIRE_COLUMNS:
            check(c in last and math.isfinite(float(last[c])), f"{tread}: column {c} missing or not finite")
        check(float(last["vertical_load"]) > 0, f"{tread}: the snow does not hold the tire up")
        check(float(last["peak_pressure"]) > 0, f"{tread}: empty footprint")
        check(float(last["accumulated"]) > 0, f"{tread}: no snow in the tread band")
        check(float(last["injected"]) > 0, f"{tread}: the conveyor injected nothing")
        check(float(last["traction"]) == float(last["tire_fx"]), f"{tread}: traction is not the tire's x force")
        frame = f"{len(rows) - 1:05d}"
        for ext in ["csv", "png"]:
            check(os.path.isfile(os.path.join(out, "footprint", frame + "." + ext)), f"{tread}: no footprint {ext}")
        with open(os.path.join(out, "footprint", frame + ".png"), "rb") as f:
            check(f.read(8) == b"\x89PNG\r\n\x1a\n", f"{tread}: footprint is not a PNG")


def test_loaded_axle():
    # A load well above what 10 ms of snow pushes back with: the axle moves down.
    _, rows = preview_run("loaded", "tire.axle=loaded", "tire.load=400", "tire.mass=5")
    start, end = float(rows[0]["axle_height"]), float(rows[-1]["axle_height"])
    check(end < start, f"loaded axle did not sink: {start} -> {end}")


def test_sweep():
    out = fresh("sweep")
    r = subprocess.run([FIRN, "sweep", SCENE, "--preview", "--jobs", "2", "--out", out, "--at", "0.01",
                        "--set", "simulation.end_time=10 ms", "--vary", "tire.tread=bowtie,six_rib"],
                       capture_output=True, text=True)
    check(r.returncode == 0, f"firn sweep exited {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    check([row["tire.tread"] for row in rows] == ["bowtie", "six_rib"], "sweep rows")
    for row in rows:
        check(row["status"] == "ok" and float(row["displaced@0.01"]) >= 0 and row["mean_traction"] != "",
              "sweep metrics missing")
    if shutil.which("gnuplot"):
        check(os.path.getsize(os.path.join(out, "plots", "accumulated.png")) > 0, "no accumulated plot")


{"treads": test_treads, "loaded_axle": test_loaded_axle, "sweep": test_sweep}[TEST]()
