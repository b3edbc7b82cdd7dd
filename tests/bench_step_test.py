"""`firn bench step --material` end to end.

Usage: python3 bench_step_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
  material: `--material thesis_hard_snow` makes the cube of that J2 snow: the run carries its plastic
            state (4 more bytes per particle, alpha) over the same 512,000 particles; an unknown
            preset is refused with exit status 2, naming the option.
  profile:  `--profile` prints each launch's time per step (the step's kernels among them) and the time
            outside launches, and the run ends in the same state as without it.
"""
import subprocess

from end_to_end import FIRN, TEST, check


def bench(*args):
    r = subprocess.run([FIRN, "bench", "step", "--steps", "1", "--threads", "1"] + list(args),
                       capture_output=True, text=True, timeout=300)
    return r, dict(line.split()[:2] for line in r.stdout.splitlines() if len(line.split()) >= 2)


if TEST == "material":
    r, plain = bench()
    check(r.returncode == 0, "plain run failed: %s" % r.stderr[-2000:])
    r, snow = bench("--material", "thesis_hard_snow")
    check(r.returncode == 0, "--material run failed: %s" % r.stderr[-2000:])
    check(snow["particles"] == plain["particles"] == "512000", "particles %s, %s" % (plain["particles"], snow["particles"]))
    check(int(snow["bytes_per_particle"]) == int(plain["bytes_per_particle"]) + 4,
          "bytes per particle %s against %s: no plastic state" % (snow["bytes_per_particle"], plain["bytes_per_particle"]))
    r, _ = bench("--material", "no_such_preset")
    check(r.returncode == 2 and "--material" in r.stderr, "unknown preset: exit %d, %s" % (r.returncode, r.stderr))

if TEST == "profile":
    r, plain = bench()
    check(r.returncode == 0, "plain run failed: %s" % r.stderr[-2000:])
    r, profiled = bench("--profile")
    check(r.returncode == 0, "--profile run failed: %s" % r.stderr[-2000:])
    check(profiled["state_hash"] == plain["state_hash"], "profiling changed the state")
    timed = {line.split()[1] for line in r.stdout.splitlines() if line.startswith("launch ")}
    for name in ["p2g", "grid_update", "g2p", "constitutive.neo_hookean", "(outside"]:
        check(name in timed, "launch table lacks %s: %s" % (name, sorted(timed)))
