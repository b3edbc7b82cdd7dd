"""`--backend` end to end (issue 14, items 2 and 4).

Usage: python3 backend_choice_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
  serial: firn run on the serial backend; summary.json names it, and its state agrees with the
          OpenMP run's to rounding in every metric (the same scene, a few steps).
  refused: where the CUDA backend cannot run (a build without it, or no device), every command
          that takes --backend answers --backend cuda with exactly one line on standard error, the
          one that says why, exit status 2 and nothing written. Skipped (exit 77) where it can run.
"""
import json
import os
import subprocess

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh

SCENE = os.path.join(ROOT, "scenes", "two_spheres.toml")
END = ["--set", "simulation.end_time=0.02"]


def firn(*args):
    return subprocess.run([FIRN] + list(args), capture_output=True, text=True, timeout=300)


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def metrics(out):
    with open(os.path.join(out, "metrics.csv")) as f:
        return [line.split(",") for line in f.read().splitlines()[1:]]


if TEST == "serial":
    runs = {}
    for backend in ["serial", "openmp"]:
        out = fresh(backend)
        r = firn("run", SCENE, "--preview", "--out", out, "--backend", backend, *END)
        check(r.returncode == 0, backend + " run failed: " + r.stderr)
        check(summary(out)["backend"] == backend, "summary.json names " + summary(out)["backend"])
        runs[backend] = metrics(out)
    check(len(runs["serial"]) == len(runs["openmp"]), "different frame counts")
    for a, b in zip(runs["serial"], runs["openmp"]):
        check(a[:5] == b[:5], "frame, step, time, dt or particles differ: %s vs %s" % (a[:5], b[:5]))
        for x, y in zip(a[5:], b[5:]):
            check(abs(float(x) - float(y)) <= 1e-4 * (abs(float(y)) + 1e-9), "metrics differ: %s vs %s" % (a, b))

elif TEST == "refused":
    probe = firn("bench", "step", "--backend", "cuda", "--steps", "1")
    if probe.returncode == 0:
        raise SystemExit(77)  # a usable CUDA device: nothing to refuse
    reason = probe.stderr.strip()
    check(reason in ("this build has no CUDA backend", "no CUDA device") or reason.startswith("the CUDA device"),
          "unexpected reason: " + probe.stderr)
    out = fresh("refused")
    commands = [
        ["run", SCENE, "--preview", "--out", out],
        ["verify", "vibrating_bar"],
        ["bench", "step", "--steps", "1"],
        ["sweep", SCENE, "--vary", "simulation.cfl=0.3,0.4", "--out", out],
        ["study", "accuracy", "--quick", "--out", out],
        ["study", "stability", "--quick", "--out", out],
    ]
    for args in commands:
        r = firn(*args, "--backend", "cuda")
        check(r.returncode == 2, "%s: exit status %d" % (args[0], r.returncode))
        check(r.stderr == reason + "\n", "%s: stderr %r" % (args[0], r.stderr))
        check(r.stdout == "", "%s: stdout %r" % (args[0], r.stdout))
        check(not os.path.exists(out), "%s wrote %s" % (args[0], out))
else:
    raise SystemExit("unknown test " + TEST)
