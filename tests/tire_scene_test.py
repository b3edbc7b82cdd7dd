"""End-to-end checks of the tire experiment (issue 5): scenes/tire_on_snow.toml at preview
resolution, for each tread and for a loaded axle, and a small `firn sweep` of it; the free-rolling
loaded wheel of scenes/tire_fresh_snow.toml (issue 16) and its sinkage and motion resistance; the
deformable rubber tire of scenes/tire_rubber_on_ground.toml (issue 17) landing on the road, the
inflated one of scenes/tire_inflated_on_ground.toml standing on its air, and the inflated tube of
scenes/inflated_tube_squeeze.toml against the membrane's contact patch.

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
FRESH_SNOW = os.path.join(ROOT, "scenes", "tire_fresh_snow.toml")
RUBBER = os.path.join(ROOT, "scenes", "tire_rubber_on_ground.toml")
INFLATED = os.path.join(ROOT, "scenes", "tire_inflated_on_ground.toml")
TUBE = os.path.join(ROOT, "scenes", "inflated_tube_squeeze.toml")
TIRE_COLUMNS = ["traction", "vertical_load", "axle_torque", "motion_resistance_coefficient", "slip_ratio",
                "axle_height", "sinkage", "peak_pressure", "displaced", "accumulated", "injected", "removed",
                "tire_fx", "ground_fy"]


def run_scene(name, scene, sets, options=()):
    # `firn run scene options --set ...` into a fresh folder: it must end ok; returns the folder and
    # metrics.csv's rows.
    out = fresh(name)
    args = [FIRN, "run", scene, *options, "--out", out]
    for s in sets:
        args += ["--set", s]
    r = subprocess.run(args, capture_output=True, text=True)
    check(r.returncode == 0, f"firn run {' '.join(sets)} exited {r.returncode}: {r.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        check(json.load(f)["status"] == "ok", "status not ok")
    with open(os.path.join(out, "metrics.csv")) as f:
        rows = list(csv.DictReader(f))
    return out, rows


def preview_run(name, *sets, scene=SCENE, end="10 ms"):
    return run_scene(name, scene, ("simulation.end_time=" + end,) + sets, ["--preview"])


def full_run(name, scene, *sets):
    # A scene at its own resolution (the inflated scenes have no preview), to its end or as `sets` say.
    return run_scene(name, scene, sets)[1]


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
        for row in rows:  # fixed axle: the tread's bottom 25 mm below the snow surface (40 + 50 mm)
            check(abs(float(row["sinkage"]) - 0.025) < 1e-9, f"{tread}: sinkage {row['sinkage']} is not 25 mm")
        for row in rows[1:]:  # fixed axle: the wheel load is the snow's vertical force
            mrc = -float(row["traction"]) / float(row["vertical_load"])
            check(math.isclose(float(row["motion_resistance_coefficient"]), mrc, rel_tol=1e-6),
                  f"{tread}: motion_resistance_coefficient is not -traction / vertical_load")
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


def test_free_wheel():
    # The 5 kN free-rolling wheel set 20 mm into the snow: it sinks, the snow resists its motion and
    # turns it at its own slip.
    _, rows = preview_run("free_wheel", scene=FRESH_SNOW, end="20 ms")
    check(abs(float(rows[0]["sinkage"]) - 0.02) < 1e-9, f"initial sinkage {rows[0]['sinkage']} is not 20 mm")
    check(abs(float(rows[0]["slip_ratio"])) < 1e-12, "a free wheel does not start rolling with the ground")
    for row in rows[1:]:  # loaded axle: the wheel load is the axle's 5 kN
        check(math.isclose(float(row["motion_resistance_coefficient"]), -float(row["traction"]) / 5000,
                           rel_tol=1e-6), "motion_resistance_coefficient is not -traction / load")
        height = float(row["axle_height"])
        check(math.isclose(float(row["sinkage"]), 0.31 - (height - 0.38), abs_tol=1e-9),
              "sinkage is not the snow surface minus the tread's bottom")
    last = rows[-1]
    check(float(last["sinkage"]) > 0.03, f"the loaded wheel did not sink: {last['sinkage']}")
    check(float(last["motion_resistance_coefficient"]) > 0, "the snow does not resist the wheel's motion")
    check(float(last["slip_ratio"]) != 0, "the free wheel's spin did not change")


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


def test_rubber_tire():
    # The deformable tire (issue 17) lands on the road by 30 ms: its rubber, not its rim, carries it
    # (the axle stays above where the rim would meet the road), the road pushes back, and the
    # rubber particles are not counted as snow; the tread stress map is written.
    out, rows = preview_run("rubber", scene=RUBBER, end="35 ms")
    heights = [float(r["axle_height"]) for r in rows]
    check(min(heights) < 0.2, f"the tire never reached the road: axle heights {heights}")
    check(min(heights) > 0.168 + 0.005, f"the rim reached the road: axle heights {heights}")
    check(max(float(r["vertical_load"]) for r in rows) > 500, "the road never pushed the tire up")
    check(all(float(r["accumulated"]) == 0 and float(r["displaced"]) == 0 for r in rows),
          "rubber particles counted as snow")
    check(not os.path.exists(os.path.join(out, "footprint")), "a rubber tire wrote a rigid tire's footprint")
    last = f"{len(rows) - 1:05d}"
    for ext in ["csv", "png"]:
        check(os.path.isfile(os.path.join(out, "tread_stress", last + "." + ext)), f"no tread stress {ext}")
    check(float(rows[-1]["peak_tread_stress"]) > 0, "the landed tread carries no stress")


def test_inflated_tire():
    # The inflated tire (issue 17 item 2) at its own resolution (it has no preview: one particle per
    # cell cannot hold a carcass in tension), 10 ms into its 20 ms inflation: the pressure has
    # done work expanding it (load_work), its air cavity's rubber is counted as tire, not snow, and
    # the road's contact patch is measured (contact_length; 0 before the tire touches it).
    rows = full_run("inflated", INFLATED, "simulation.end_time=10 ms")
    last = rows[-1]
    check(float(last["load_work"]) > 0, f"the pressure did no work: load_work {last['load_work']}")
    check(math.isfinite(float(last["contact_length"])) and float(last["contact_length"]) >= 0,
          f"contact_length {last['contact_length']}")
    check(float(last["displaced"]) == 0 and float(last["accumulated"]) == 0, "rubber particles counted as snow")
    # Sidewalls of a material of their own (a bimodular one, as README's Inflation measures) are
    # tire too: none of them counted as snow inside the tire (accumulated).
    rows = full_run("inflated_sidewalls", INFLATED, "simulation.end_time=5 ms", "materials.side.model=bimodular",
                    "materials.side.density=1100", "materials.side.E=200 MPa", "materials.side.nu=0",
                    "materials.side.compression_ratio=0.05", "tire.sidewall_material=side")
    check(all(float(r["displaced"]) == 0 and float(r["accumulated"]) == 0 for r in rows),
          "sidewall particles counted as snow")


def test_inflated_tube():
    # The membrane estimate (issue 17 item 6): an inflated tube squeezed between plates has
    # F = p w L, so contact_length follows -road_fy / (p w). The reading steps by a lattice row at
    # each end (29, 50, 67, 75, 88, 97, 106 mm as the plate comes down), so every frame from three
    # rows of patch on is checked to lie between 0.85 times the estimate and the estimate plus
    # 30 mm (measured: 0.93 times, plus 21.4 mm). A pressure on half or twice the area, or a plate
    # carried by anything but the air, leaves that band. Both plates carry the same force.
    rows = full_run("inflated_tube", TUBE)
    p, w = 150e3, 0.020
    pairs = [(-float(row["road_fy"]) / (p * w), float(row["contact_length"])) for row in rows]
    pairs = [(e, length) for e, length in pairs if e >= 0.03]
    check(len(pairs) >= 15, f"only {len(pairs)} frames with F / (p w) of 30 mm or more")
    check(pairs[-1][0] > 0.09, f"the plate did not squeeze the tube: F / (p w) {pairs[-1][0]} m at the end")
    for e, length in pairs:
        check(0.85 * e < length < e + 0.030, f"a patch of {length} m where F / (p w) is {e} m")
    last = rows[-1]
    check(math.isclose(-float(last["road_fy"]), float(last["plate_fy"]), rel_tol=0.05),
          f"road {last['road_fy']} N against plate {last['plate_fy']} N")


{"treads": test_treads, "loaded_axle": test_loaded_axle, "free_wheel": test_free_wheel, "sweep": test_sweep,
 "rubber_tire": test_rubber_tire, "inflated_tire": test_inflated_tire, "inflated_tube": test_inflated_tube}[TEST]()
