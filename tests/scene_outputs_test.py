"""End-to-end checks of `firn run` and its outputs (issue "Scenes, firn run and outputs").

Usage: python3 scene_outputs_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
Runs the snowball_pair scene at preview resolution and checks what a user relies on: every
output file, the summary, momentum conservation while the balls fly and collide, that each .vtp
opens in VTK's own vtkXMLPolyDataReader with the expected points and arrays, that re-running
scene.resolved.toml reproduces the final state bit for bit, that SIGINT leaves valid frames and
an `interrupted` summary, that --profile times the launches without changing the run, that
summary.json says how idle OpenMP threads waited, and that docs/scenes.md is what
`firn help scene-keys` prints.
"""
import csv
import glob
import json
import os
import signal
import subprocess
import time

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh
SCENE = os.path.join(ROOT, "scenes", "snowball_pair.toml")


def run(args, **kw):
    return subprocess.run([FIRN] + args, capture_output=True, text=True, **kw)




def preview_run(name, *sets):
    out = fresh(name)
    args = ["run", SCENE, "--preview", "--out", out, "--set", "simulation.end_time=4 ms"]
    for s in sets:
        args += ["--set", s]
    r = run(args)
    check(r.returncode == 0, f"firn run exited {r.returncode}: {r.stderr}")
    return out


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def metrics(out):
    with open(os.path.join(out, "metrics.csv")) as f:
        return list(csv.DictReader(f))


def test_outputs():
    out = preview_run("outputs")
    for name in ["scene.resolved.toml", "metrics.csv", "summary.json"]:
        check(os.path.isfile(os.path.join(out, name)), f"{name} missing")
    check(not glob.glob(os.path.join(out, "**", "*.tmp"), recursive=True), "temporary files left behind")
    s = summary(out)
    check(s["status"] == "ok" and s["error"] is None, f"summary: {s}")
    for key in ["steps", "particles", "wall_seconds", "step_seconds", "particle_steps_per_second", "threads",
                "openmp_wait", "backend", "precision", "peak_memory_mb"]:
        check(key in s, f"summary.json lacks {key}")
    rows = metrics(out)
    header = ("frame,step,time,dt,particles,kinetic_energy,elastic_energy,momentum_x,momentum_y,momentum_z,"
              "max_speed,min_J").split(",")
    check(list(rows[0].keys())[:len(header)] == header, f"metrics.csv header {list(rows[0].keys())}")
    frames = sorted(glob.glob(os.path.join(out, "particles", "*.vtp")))
    check(len(frames) == len(rows), f"{len(frames)} frames for {len(rows)} metrics rows")
    check(float(rows[-1]["min_J"]) < 0.999, "the balls never compressed: did they collide?")


def momentum_drift(out):
    rows = metrics(out)
    # |p| scale: the sum of the balls' |momentum|, from the initial kinetic energy and speed.
    scale = 2 * float(rows[0]["kinetic_energy"]) / float(rows[0]["max_speed"])
    p0 = [float(rows[0][f"momentum_{a}"]) for a in "xyz"]
    return max(abs(float(r[f"momentum_{a}"]) - p0[i]) for r in rows for i, a in enumerate("xyz")) / scale


def test_momentum():
    drift_double = momentum_drift(preview_run("momentum_double", "simulation.precision=double"))
    drift_float = momentum_drift(preview_run("momentum_float"))
    print(f"relative momentum drift: double {drift_double:.3g}, float {drift_float:.3g}")
    check(drift_double < 1e-12, f"double-precision momentum drift {drift_double}")
    check(drift_float < 1e-5, f"float momentum drift {drift_float}")


def test_vtp():
    import vtk  # Debian's python3-vtk9
    out = preview_run("vtp")
    n = summary(out)["particles"]
    frames = sorted(glob.glob(os.path.join(out, "particles", "*.vtp")))
    for path in frames:
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        poly = reader.GetOutput()
        check(poly.GetNumberOfPoints() == n, f"{path}: {poly.GetNumberOfPoints()} points, expected {n}")
        check(poly.GetNumberOfVerts() == n, f"{path}: {poly.GetNumberOfVerts()} vertices")
        data = poly.GetPointData()
        for name, comps in [("velocity", 3), ("id", 1), ("material", 1), ("J", 1), ("von_mises", 1),
                            ("plastic_strain", 1)]:
            array = data.GetArray(name)
            check(array is not None, f"{path}: no array {name}")
            check(array.GetNumberOfComponents() == comps and array.GetNumberOfTuples() == n,
                  f"{path}: array {name} has {array.GetNumberOfComponents()}x{array.GetNumberOfTuples()}")
        ids = data.GetArray("id")
        check(all(ids.GetValue(i) == i for i in range(0, n, max(1, n // 97))), f"{path}: points not in id order")
    print(f"{len(frames)} frames of {n} points read by vtkXMLPolyDataReader")


def test_rerun_resolved():
    out = preview_run("first")
    again = fresh("again")
    r = run(["run", os.path.join(out, "scene.resolved.toml"), "--out", again])
    check(r.returncode == 0, f"re-running scene.resolved.toml exited {r.returncode}: {r.stderr}")
    a, b = summary(out), summary(again)
    check(a["state_hash"] == b["state_hash"] and a["steps"] == b["steps"],
          f"re-run differs: {a['state_hash']} after {a['steps']} steps vs {b['state_hash']} after {b['steps']}")


def test_profile():
    """--profile times the step's launches into summary.json without changing the run."""
    plain = preview_run("unprofiled")
    out = fresh("profiled")
    r = run(["run", SCENE, "--preview", "--out", out, "--set", "simulation.end_time=4 ms", "--profile"])
    check(r.returncode == 0, f"firn run --profile exited {r.returncode}: {r.stderr}")
    s = summary(out)
    check(s["state_hash"] == summary(plain)["state_hash"], "profiling changed the final state")
    launches = s.get("launch_seconds", {})
    for name in ["p2g", "grid_update", "g2p", "constitutive.hyperelastic_plastic"]:
        check(launches.get(name, 0) > 0, f"launch_seconds lacks {name}: {launches}")
    check(sum(launches.values()) <= s["step_seconds"], f"launches take {sum(launches.values())} s of {s['step_seconds']} s")
    check("p2g" in r.stdout and "(outside launches)" in r.stdout, f"no launch table printed: {r.stdout}")
    check("launch_seconds" not in summary(plain), "a run without --profile writes launch_seconds")


def test_wait():
    """firn chooses how idle OpenMP threads wait unless the user did, and summary.json says which."""
    cases = [({"OMP_WAIT_POLICY": "active"}, {"active"}), ({"GOMP_SPINCOUNT": "777"}, {"spin:777"}),
             ({}, {"spin:10000", "passive"})]  # which of the two depends on what else runs
    base = {k: v for k, v in os.environ.items() if k not in ("OMP_WAIT_POLICY", "GOMP_SPINCOUNT")}
    for i, (env, expected) in enumerate(cases):
        out = fresh(f"wait{i}")
        r = run(["run", SCENE, "--preview", "--out", out, "--set", "simulation.end_time=1 ms"], env={**base, **env})
        check(r.returncode == 0, f"firn run exited {r.returncode}: {r.stderr}")
        check(summary(out)["openmp_wait"] in expected, f"{env}: openmp_wait {summary(out)['openmp_wait']}")
    b = run(["bench", "step", "--steps", "1", "--threads", "1"], env={**base, "GOMP_SPINCOUNT": "5"})
    check("openmp_wait spin:5\n" in b.stdout, f"firn bench step: {b.stdout}")


def test_no_particles():
    """[output] particles = false writes no .vtp and leaves the run and its other outputs as they were."""
    plain = preview_run("with_particles")
    out = preview_run("no_particles", "output.particles=false")
    check(not os.path.exists(os.path.join(out, "particles")), "output.particles = false made particles/")
    check(glob.glob(os.path.join(plain, "particles", "*.vtp")), "the default run wrote no .vtp")
    a, b = summary(plain), summary(out)
    check(a["state_hash"] == b["state_hash"] and a["steps"] == b["steps"], "output.particles changed the run")
    check(len(metrics(out)) == len(metrics(plain)), "output.particles changed metrics.csv's frames")
    r = run(["render", out])
    check(r.returncode == 2 and "output.particles = false" in r.stderr, f"firn render without particles: {r.stderr}")
    r = run(["run", SCENE, "--preview", "--out", plain, "--set", "simulation.end_time=4 ms", "--set", "output.particles=false"])
    check(r.returncode == 0 and not os.path.exists(os.path.join(plain, "particles")),
          "a run without particle frames left an earlier run's frames in its folder")


def test_interrupt():
    out = fresh("interrupt")
    p = subprocess.Popen([FIRN, "run", SCENE, "--preview", "--out", out, "--threads", "1",
                          "--set", "simulation.end_time=1 s"], stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while not os.path.exists(os.path.join(out, "particles", "00003.vtp")) and time.time() < deadline:
        time.sleep(0.05)
    p.send_signal(signal.SIGINT)
    err = p.communicate(timeout=120)[1]
    check(p.returncode == 130, f"exit status {p.returncode} after SIGINT: {err}")
    s = summary(out)
    check(s["status"] == "interrupted" and s["error"], f"summary after SIGINT: {s}")
    import vtk
    frames = sorted(glob.glob(os.path.join(out, "particles", "*.vtp")))
    check(len(frames) >= 4, f"only {len(frames)} frames before the interrupt")
    for path in frames:
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        check(reader.GetOutput().GetNumberOfPoints() == s["particles"], f"{path} is not a complete frame")
    check(len(metrics(out)) == len(frames), "metrics.csv rows and frames disagree after the interrupt")


def test_unstable():
    out = fresh("unstable")
    # A fixed time step far above the CFL limit: the stability guard must stop the run.
    r = run(["run", SCENE, "--preview", "--out", out, "--set", "simulation.fixed_dt=2 ms"])
    check(r.returncode == 1, f"exit status {r.returncode} for an unstable run: {r.stderr}")
    check(r.stderr.count("\n") == 1 and "stability guard" in r.stderr, f"stderr: {r.stderr}")
    s = summary(out)
    check(s["status"] == "unstable" and "particle" in s["error"], f"summary: {s}")
    with open(os.path.join(out, "metrics.csv")) as f:
        check("nan" not in f.read().lower(), "a NaN reached metrics.csv")


def test_docs():
    r = run(["help", "scene-keys"])
    with open(os.path.join(ROOT, "docs", "scenes.md")) as f:
        check(f.read() == r.stdout, "docs/scenes.md is stale: regenerate with `firn help scene-keys > docs/scenes.md`")


def test_check():
    r = run(["check", SCENE])
    check(r.returncode == 0, f"firn check exited {r.returncode}: {r.stderr}")
    for word in ["particles", "blocks_touched", "dt_first", "memory_estimate_mb"]:
        check(word in r.stdout, f"firn check does not print {word}: {r.stdout}")


def read_ply(path):
    """Vertices and triangles of a binary little-endian PLY as firn writes it."""
    import struct
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    check(header[1] == "format binary_little_endian 1.0", f"{path}: not binary little-endian")
    vertices = int([l for l in header if l.startswith("element vertex")][0].split()[2])
    faces = int([l for l in header if l.startswith("element face")][0].split()[2])
    floats = len([l for l in header if l.startswith("property float")])
    at = end + 4 * floats * vertices
    triangles = []
    for _ in range(faces):
        count = data[at]
        check(count == 3, f"{path}: a face with {count} vertices")
        triangles.append(struct.unpack_from("<3I", data, at + 1))
        at += 13
    check(at == len(data), f"{path}: {len(data) - at} bytes after the faces")
    return vertices, triangles


def test_mesh():
    # --mesh writes one PLY per frame, each a closed, consistently oriented manifold: every
    # directed edge appears once and its reverse once.
    out = fresh("mesh_run")
    r = run(["run", SCENE, "--preview", "--mesh", "--out", out, "--set", "simulation.end_time=2 ms"])
    check(r.returncode == 0, f"firn run --mesh exited {r.returncode}: {r.stderr}")
    frames = sorted(glob.glob(os.path.join(out, "meshes", "*.ply")))
    check(len(frames) == len(metrics(out)), f"{len(frames)} meshes for {len(metrics(out))} frames")
    for path in frames:
        vertices, triangles = read_ply(path)
        check(len(triangles) > 1000, f"{path}: only {len(triangles)} triangles")
        edges = {}
        for a, b, c in triangles:
            check(max(a, b, c) < vertices, f"{path}: vertex index out of range")
            for e in ((a, b), (b, c), (c, a)):
                edges[e] = edges.get(e, 0) + 1
        check(all(n == 1 for n in edges.values()), f"{path}: an edge used twice the same way (not oriented or not manifold)")
        check(all((b, a) in edges for a, b in edges), f"{path}: an open edge (the surface is not closed)")


os.makedirs(SCRATCH, exist_ok=True)
globals()["test_" + TEST]()
print("ok")
