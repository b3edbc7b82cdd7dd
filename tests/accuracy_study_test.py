"""End-to-end check of `firn study accuracy` (issue 8).

Usage: python3 accuracy_study_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
quick_bar: `firn study accuracy --quick --problems vibrating_bar` writes one accuracy.csv row per
level and method (2 levels x 12 methods) with finite errors and run times, at least one case on the
Pareto front, accuracy.md with the problem's section, and the plot where gnuplot is installed.
bad_problem: an unknown problem is refused with exit status 2 before anything is written.
missing_scenes: snowball_pair_energy without its scene file is refused the same way, naming --scenes.
"""
import csv
import math
import os
import shutil
import subprocess

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh


def study(out, *args):
    return subprocess.run([FIRN, "study", "accuracy", "--out", out, "--threads", "1"] + list(args),
                          capture_output=True, text=True, timeout=300)


if TEST == "quick_bar":
    out = fresh("quick_bar")
    r = study(out, "--quick", "--problems", "vibrating_bar")
    check(r.returncode == 0, "exit status %d: %s" % (r.returncode, r.stderr[-2000:]))
    with open(os.path.join(out, "accuracy.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 24, "%d rows, expected 2 levels x 12 methods" % len(rows))
    check({(r["transfer"], r["shape"], r["precision"]) for r in rows} ==
          {(t, s, p) for t in ("apic", "pic", "flip") for s in ("quadratic", "cubic") for p in ("float", "double")},
          "not every method ran")
    for row in rows:
        check(row["status"] == "ok" and math.isfinite(float(row["error"])) and float(row["seconds"]) > 0,
              "bad row %s" % row)
    check(any(r["pareto"] == "1" for r in rows), "no case on the Pareto front")
    with open(os.path.join(out, "accuracy.md")) as f:
        check("## vibrating_bar" in f.read(), "accuracy.md has no vibrating_bar section")
    if shutil.which("gnuplot"):
        check(os.path.getsize(os.path.join(out, "vibrating_bar.png")) > 0, "no vibrating_bar.png")
elif TEST == "bad_problem":
    out = fresh("bad_problem")
    r = study(out, "--problems", "no_such_problem")
    check(r.returncode == 2, "exit status %d, expected 2" % r.returncode)
    check(not os.path.exists(out), "the study wrote %s" % out)
elif TEST == "missing_scenes":
    out = fresh("missing_scenes")
    r = study(out, "--problems", "snowball_pair_energy", "--scenes", os.path.join(SCRATCH, "no_such_folder"))
    check(r.returncode == 2, "exit status %d, expected 2" % r.returncode)
    check("snowball_pair.toml" in r.stderr and "--scenes" in r.stderr, "unclear message: %s" % r.stderr)
    check(not os.path.exists(out), "the study wrote %s" % out)
else:
    check(False, "unknown test " + TEST)
