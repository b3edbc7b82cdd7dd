"""An installed firn used from another folder (issue 20, item 2).

Usage: python3 install_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
Installs the build that holds FIRN (cmake --install) into a fresh prefix under SCRATCH_DIR, then
runs the installed firn from a folder that holds no scenes:
  help_scenes    `firn help scenes` lists every scene of the repository's scenes/;
  run_by_name    `firn run snowball_pair --preview` (shortened) finds the shipped scene, and
                 `firn check` and `firn sweep` take a name too;
  local_first    a snowball_pair.toml in the current folder comes before the shipped one;
  unknown_scene  an unknown name is refused with exit status 2 and one line naming where firn
                 looked, and nothing is written.
"""
import glob
import json
import os
import subprocess

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh


def install():
    """Installs into SCRATCH/TEST/prefix; returns (installed firn, an empty working folder)."""
    base = fresh(TEST)
    prefix = os.path.join(base, "prefix")
    r = subprocess.run(["cmake", "--install", os.path.dirname(FIRN), "--prefix", prefix],
                       capture_output=True, text=True, timeout=120)
    check(r.returncode == 0, "cmake --install failed: " + r.stdout + r.stderr)
    firn = os.path.join(prefix, "bin", "firn")
    check(os.access(firn, os.X_OK), firn + " was not installed")
    for doc in ["README.md", "scenes.md"]:
        check(os.path.isfile(os.path.join(prefix, "share", "doc", "firn", doc)), doc + " was not installed")
    work = os.path.join(base, "work")
    os.makedirs(work)
    return firn, work


def firn_in(work, firn, *args):
    return subprocess.run([firn] + list(args), cwd=work, capture_output=True, text=True, timeout=300)


SHORT = ["--preview", "--set", "simulation.end_time=0.002", "--set", "simulation.frame_interval=0.001"]

firn, work = install()
if TEST == "help_scenes":
    r = firn_in(work, firn, "help", "scenes")
    check(r.returncode == 0, "firn help scenes failed: " + r.stderr)
    check("share/firn/scenes" in r.stdout, "the listing does not name the installed folder: " + r.stdout)
    for path in glob.glob(os.path.join(ROOT, "scenes", "*.toml")):
        name = os.path.basename(path)[:-5]
        check(("\n  " + name + " ") in r.stdout, name + " is not listed: " + r.stdout)
elif TEST == "run_by_name":
    r = firn_in(work, firn, "run", "snowball_pair", "--out", "run", *SHORT)
    check(r.returncode == 0, "firn run snowball_pair failed: " + r.stderr)
    with open(os.path.join(work, "run", "summary.json")) as f:
        check(json.load(f)["status"] == "ok", "the run's summary is not ok")
    r = firn_in(work, firn, "check", "tire_on_snow", "--preview")
    check(r.returncode == 0 and "scene tire_on_snow" in r.stdout, "firn check tire_on_snow failed: " + r.stderr)
    r = firn_in(work, firn, "sweep", "two_spheres", "--out", "sweep", "--vary", "simulation.cfl=0.3,0.4", *SHORT)
    check(r.returncode == 0, "firn sweep two_spheres failed: " + r.stderr)
    check(len(open(os.path.join(work, "sweep", "sweep.csv")).read().splitlines()) == 3, "sweep.csv lacks rows")
elif TEST == "local_first":
    with open(os.path.join(ROOT, "scenes", "snowball_pair.toml")) as f:
        local = f.read().replace("[simulation]", "[simulation]\ncfl = 0.123", 1)
    check("cfl = 0.123" in local, "scenes/snowball_pair.toml has no [simulation] table")
    with open(os.path.join(work, "snowball_pair.toml"), "w") as f:
        f.write(local)
    r = firn_in(work, firn, "run", "snowball_pair", "--out", "run", *SHORT)
    check(r.returncode == 0, "firn run of the local snowball_pair failed: " + r.stderr)
    with open(os.path.join(work, "run", "scene.resolved.toml")) as f:
        check("cfl = 0.123" in f.read(), "the run did not use ./snowball_pair.toml")
elif TEST == "unknown_scene":
    r = firn_in(work, firn, "run", "no_such_scene", "--out", "run")
    check(r.returncode == 2, "exit status %d, expected 2" % r.returncode)
    lines = r.stderr.strip().splitlines()
    check(len(lines) == 1 and "share/firn/scenes/no_such_scene.toml" in lines[0] and "firn help scenes" in lines[0],
          "the message does not say where firn looked: " + r.stderr)
    check(not os.path.exists(os.path.join(work, "run")), "an output folder was written")
else:
    check(False, "unknown test " + TEST)
print("ok")
