"""End-to-end checks of checkpoints: `firn run --checkpoint-every` and `firn run --resume`.

Usage: python3 checkpoint_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
A run killed with SIGKILL (or stopped with SIGINT) part way and resumed must end with the
uninterrupted run's state_hash and the same metrics.csv, byte for byte (no duplicate or missing
rows); the tire scene's conveyor and loaded axle too; a checkpoint of another scene or another firn
or a damaged one is refused with exit status 2, and so is a run without a checkpoint; a guard stop
leaves a checkpoint whose resume stops the same way.
"""
import json
import os
import shutil
import signal
import subprocess
import time

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh

PAIR = [os.path.join(ROOT, "scenes", "snowball_pair.toml"), "--preview", "--set", "simulation.end_time=30 ms"]
TIRE = [os.path.join(ROOT, "scenes", "tire_on_snow.toml"), "--preview", "--set", "simulation.end_time=30 ms",
        "--set", "tire.axle=\"loaded\"", "--set", "tire.load=400"]


def run(args):
    return subprocess.run([FIRN] + args, capture_output=True, text=True)


def read(out, name):
    with open(os.path.join(out, name)) as f:
        return f.read()


def summary(out):
    return json.loads(read(out, "summary.json"))


def uninterrupted(name, scene):
    out = fresh(name)
    r = run(["run"] + scene + ["--out", out, "--threads", "1"])
    check(r.returncode == 0, f"uninterrupted run exited {r.returncode}: {r.stderr}")
    return out


def stopped(name, scene, sig, every, halfway_frame):
    """Starts a run that checkpoints every `every` and stops it with `sig` once it has written a
    checkpoint and output frame `halfway_frame`."""
    out = fresh(name)
    p = subprocess.Popen([FIRN, "run"] + scene + ["--out", out, "--threads", "1", "--checkpoint-every", every],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wanted = [os.path.join(out, "checkpoint.firn"), os.path.join(out, "particles", f"{halfway_frame:05d}.vtp")]
    deadline = time.time() + 300
    while not all(map(os.path.exists, wanted)) and p.poll() is None and time.time() < deadline:
        time.sleep(0.02)
    if p.poll() is not None:
        check(False, f"the run ended before it was stopped: {p.communicate()[1]}")
    p.send_signal(sig)
    err = p.communicate(timeout=300)[1]
    return out, p.returncode, err


def resume(out, *extra):
    r = run(["run", "--resume", out, "--threads", "2"] + list(extra))
    check(r.returncode == 0, f"firn run --resume exited {r.returncode}: {r.stderr}")
    return r


def expect_same_run(resumed, whole):
    a, b = summary(resumed), summary(whole)
    check(a["status"] == "ok", f"resumed run: {a}")
    check(a["state_hash"] == b["state_hash"] and a["steps"] == b["steps"],
          f"resumed run ends at {a['state_hash']} after {a['steps']} steps, the uninterrupted one at "
          f"{b['state_hash']} after {b['steps']}")
    check(read(resumed, "metrics.csv") == read(whole, "metrics.csv"), "metrics.csv differs from the uninterrupted run's")


def test_kill():
    whole = uninterrupted("kill_whole", PAIR)
    out, status, err = stopped("kill", PAIR, signal.SIGKILL, "4 ms", 30)
    check(status == -signal.SIGKILL, f"exit status {status} after SIGKILL")
    check(not os.path.exists(os.path.join(out, "summary.json")), "a killed run wrote summary.json")
    resume(out)
    expect_same_run(out, whole)


def test_interrupt():
    whole = uninterrupted("interrupt_whole", PAIR)
    out, status, err = stopped("interrupt", PAIR, signal.SIGINT, "4 ms", 30)
    check(status == 130, f"exit status {status} after SIGINT: {err}")
    check("firn run --resume " + out in err, f"the interrupted run does not say how to resume: {err}")
    check(summary(out)["status"] == "interrupted", "summary after SIGINT")
    resume(out)
    expect_same_run(out, whole)
    r = run(["run", "--resume", out])
    check(r.returncode == 0 and "nothing to resume" in r.stdout, f"resuming a finished run: {r.stdout} {r.stderr}")


def test_conveyor():
    whole = uninterrupted("conveyor_whole", TIRE)
    out, status, err = stopped("conveyor", TIRE, signal.SIGKILL, "5 ms", 1)
    resume(out)
    expect_same_run(out, whole)


def test_guard():
    # A guard stop leaves the last output frame's state; resuming it stops at the same step, with the
    # same message and the same metrics.csv (the run is deterministic).
    out = fresh("guard")
    r = run(["run"] + PAIR + ["--out", out, "--set", "simulation.fixed_dt=0.3 ms", "--checkpoint-every", "1 ms"])
    check(r.returncode == 1 and "stability guard" in r.stderr and "checkpoint.firn" in r.stderr,
          f"unstable run: {r.returncode}: {r.stderr}")
    first, metrics = summary(out), read(out, "metrics.csv")
    check(first["status"] == "unstable" and first["steps"] > 4, f"summary: {first}")
    r = run(["run", "--resume", out])
    check(r.returncode == 1 and summary(out)["error"] == first["error"] and read(out, "metrics.csv") == metrics,
          f"resumed unstable run: {r.returncode}: {r.stderr}")


def refused(args, words):
    r = run(args)
    check(r.returncode == 2, f"{args} exited {r.returncode}, expected 2: {r.stderr}")
    check(all(w in r.stderr for w in words), f"{args}: message lacks {words}: {r.stderr}")


def test_refused():
    pair, _, _ = stopped("refused_pair", PAIR, signal.SIGINT, "4 ms", 2)
    other = fresh("refused_other")
    r = run(["run"] + PAIR + ["--out", other, "--set", "simulation.cfl=0.3", "--set", "simulation.end_time=1 ms"])
    check(r.returncode == 0, f"short run exited {r.returncode}: {r.stderr}")
    os.remove(os.path.join(other, "summary.json"))  # as if it had been killed before it wrote one
    refused(["run", "--resume", other], ["no checkpoint"])
    shutil.copy(os.path.join(pair, "checkpoint.firn"), other)
    refused(["run", "--resume", other], ["another scene"])
    with open(os.path.join(pair, "checkpoint.firn"), "rb") as f:
        data = bytearray(f.read())
    damaged = bytearray(data)
    damaged[len(damaged) // 2] ^= 0x10  # a bit flipped in the particles
    with open(os.path.join(pair, "checkpoint.firn"), "wb") as f:
        f.write(bytes(damaged))
    refused(["run", "--resume", pair], ["damaged"])
    at = data.index(b"0.1.0")  # firn's version, after the magic and the format
    data[at:at + 5] = b"9.9.9"
    with open(os.path.join(pair, "checkpoint.firn"), "wb") as f:
        f.write(bytes(data))
    refused(["run", "--resume", pair], ["written by firn 9.9.9"])
    refused(["run", "--resume", pair, "--set", "simulation.cfl=0.2"], ["--resume", "--set"])
    refused(["run", PAIR[0], "--checkpoint-every", "5 kg"], ["--checkpoint-every"])


{"kill": test_kill, "interrupt": test_interrupt, "conveyor": test_conveyor, "guard": test_guard,
 "refused": test_refused}[TEST]()
