"""End-to-end checks of `firn sweep` (issue 5, item 7; DESIGN.md section 5).

Usage: python3 sweep_test.py FIRN REPO_ROOT SCRATCH_DIR TEST
Sweeps the tiny two_spheres scene at preview resolution: a 2x2 product run two at a time gives one
sweep.csv row per combination in product order with the runs' statuses and counts, and each child
run really got its values; an unstable combination is reported in its row and makes the exit
status 1; a bad value or list is refused with exit status 2 before anything is written; SIGINT
stops the sweep with exit status 130, the running child interrupted and sweep.csv holding the runs
that finished; a sweep killed with SIGKILL resumes with --resume to the uninterrupted runs' states.
"""
import csv
import glob
import json
import os
import re
import signal
import subprocess
import time

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh
SCENE = os.path.join(ROOT, "scenes", "two_spheres.toml")
RUN_COLUMNS = ["status", "steps", "particles", "wall_seconds", "particle_steps_per_second"]




def sweep(out, *args):
    return subprocess.run([FIRN, "sweep", SCENE, "--preview", "--out", out, "--set", "simulation.end_time=0.1"] +
                          list(args), capture_output=True, text=True, timeout=300)


def table(out):
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        return list(csv.reader(f))


def summary(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        return json.load(f)


def test_product():
    out = fresh("product")
    r = sweep(out, "--vary", "bodies.0.velocity=[0.1,0.1,0],[0.2, 0.2, 0]", "--vary", "simulation.transfer=pic,apic",
              "--jobs", "2", "--at", "0.05,100 ms")
    check(r.returncode == 0, f"exit status {r.returncode}: {r.stderr}")
    rows = table(out)
    header, rows = rows[0], rows[1:]
    keys = ["bodies.0.velocity", "simulation.transfer"]
    check(header[:7] == keys + RUN_COLUMNS, f"sweep.csv header {header}")
    # Each metric after min_J (the energy budget; two_spheres has no scene metrics of its own) comes as
    # mean_C, then C@T for the two --at times.
    extra = header[7:]
    groups = [extra[i:i + 3] for i in range(0, len(extra), 3)]
    check(len(extra) > 0 and all(g == [g[0], g[0][5:] + "@0.05", g[0][5:] + "@0.1"] and g[0].startswith("mean_")
                                 for g in groups), f"scene-metric columns {extra}")
    check([g[0] for g in groups] == ["mean_plastic_work", "mean_gravity_work", "mean_collider_work", "mean_load_work",
                                     "mean_energy_residual"], f"scene-metric columns {extra}")
    expected = [["[0.1,0.1,0]", "pic"], ["[0.1,0.1,0]", "apic"], ["[0.2, 0.2, 0]", "pic"], ["[0.2, 0.2, 0]", "apic"]]
    check([row[:2] for row in rows] == expected, f"rows not in product order: {rows}")
    check(all(len(row) == len(header) for row in rows), "rows and header differ in length")
    cores = len(os.sched_getaffinity(0))
    run_dirs = sorted(glob.glob(os.path.join(out, "runs", "*")))
    names = [os.path.basename(d) for d in run_dirs]
    check(names == ["001_0.1-0.1-0_pic", "002_0.1-0.1-0_apic", "003_0.2-0.2-0_pic", "004_0.2-0.2-0_apic"],
          f"run folders {names}")
    for row, run_dir in zip(rows, run_dirs):
        s = summary(run_dir)
        check(row[2] == "ok" and s["status"] == "ok", f"{run_dir}: {row}")
        check(int(row[3]) == s["steps"] > 0 and int(row[4]) == s["particles"] > 0, f"{run_dir}: {row} vs {s}")
        check(s["threads"] == max(1, cores // 2), f"{run_dir} ran on {s['threads']} threads with {cores} cores")
        check(os.path.isfile(os.path.join(run_dir, "log.txt")), f"{run_dir}/log.txt missing")
        with open(os.path.join(run_dir, "scene.resolved.toml")) as f:
            resolved = f.read()
        check(re.search(rf"^transfer = [\"']{row[1]}[\"']$", resolved, re.M),
              f"{run_dir} did not run with transfer {row[1]}")
        with open(os.path.join(run_dir, "metrics.csv")) as f:
            first = next(csv.DictReader(f))
        check(abs(float(first["max_speed"]) - 2 ** 0.5 * float(row[0][1:4])) < 1e-6,
              f"{run_dir} did not start at {row[0]}: max_speed {first['max_speed']}")
    check(not glob.glob(os.path.join(out, "**", "*.tmp"), recursive=True), "temporary files left behind")
    progress = [line for line in r.stderr.splitlines() if "/4]" in line]
    check(len(progress) == 4, f"expected one progress line per run: {r.stderr}")


def test_statuses():
    out = fresh("statuses")
    # A fixed time step far above the CFL limit of the fast sphere: the stability guard stops it.
    r = sweep(out, "--set", "simulation.fixed_dt=0.05", "--vary", "bodies.0.velocity=[0.1,0.1,0],[5,5,0]")
    check(r.returncode == 1, f"exit status {r.returncode} with an unstable run: {r.stderr}")
    rows = table(out)[1:]
    check([row[:2] for row in rows] == [["[0.1,0.1,0]", "ok"], ["[5,5,0]", "unstable"]], f"rows {rows}")
    check("unstable" in r.stderr and "log.txt" in r.stderr, f"stderr does not point at the log: {r.stderr}")


def test_bad_input():
    for name, args in [
        ("bad_value", ["--vary", "simulation.transfer=pic,nonsense"]),
        ("bad_key", ["--vary", "simulation.trasnfer=pic,apic"]),
        ("empty_value", ["--vary", "simulation.transfer=pic,,apic"]),
        ("unbalanced", ["--vary", "bodies.0.velocity=[0,0,1],[0,0,2"]),
        ("twice", ["--vary", "simulation.transfer=pic", "--vary", "simulation.transfer=apic"]),
        ("bad_at", ["--vary", "simulation.transfer=pic", "--at", "5 kg"]),
        ("bad_set", ["--vary", "simulation.transfer=pic,apic", "--set", "simulation.dx=-1"]),
    ]:
        out = fresh(name)
        r = sweep(out, *args)
        check(r.returncode == 2, f"{name}: exit status {r.returncode}: {r.stderr}")
        check(r.stderr.count("\n") == 1, f"{name}: not one line on stderr: {r.stderr!r}")
        check(not os.path.exists(out), f"{name}: {out} was written")


def test_collect():
    # --collect rebuilds sweep.csv from DIR/sweep.args and the runs' outputs, here of a local sweep.
    out = fresh("collect")
    r = sweep(out, "--vary", "simulation.transfer=pic,apic", "--at", "0.05")
    check(r.returncode == 0, f"exit status {r.returncode}: {r.stderr}")
    before = table(out)
    os.remove(os.path.join(out, "sweep.csv"))
    r = subprocess.run([FIRN, "sweep", "--collect", out], capture_output=True, text=True, timeout=120)
    check(r.returncode == 0 and "2 of 2 runs finished" in r.stderr, f"--collect: {r.returncode}: {r.stderr}")
    check(table(out) == before, f"--collect wrote {table(out)}, the sweep {before}")
    os.remove(os.path.join(out, "runs", "002_apic", "summary.json"))
    r = subprocess.run([FIRN, "sweep", "--collect", out], capture_output=True, text=True, timeout=120)
    check(r.returncode == 1 and "not yet: run 2" in r.stderr, f"--collect with a run missing: {r.returncode}: {r.stderr}")
    check(table(out) == before[:2], f"--collect with a run missing wrote {table(out)}")
    # Mistakes: exit status 2 and one line.
    for args in [["--collect", out, SCENE], ["--collect", os.path.join(out, "runs")], [SCENE],
                 [SCENE, "--vary", "simulation.transfer=pic", "--sbatch=--partition=x"]]:
        r = subprocess.run([FIRN, "sweep"] + args, capture_output=True, text=True, timeout=120)
        check(r.returncode == 2 and r.stderr.count("\n") == 1, f"firn sweep {args}: {r.returncode}: {r.stderr!r}")
    # --scheduler slurm where there is no sbatch: the job script is written, the failure named.
    out = fresh("no_sbatch")
    r = subprocess.run([FIRN, "sweep", SCENE, "--out", out, "--scheduler", "slurm", "--vary", "simulation.transfer=pic,apic"],
                       capture_output=True, text=True, timeout=120, env=dict(os.environ, PATH="/nonexistent"))
    check(r.returncode == 1 and "sbatch" in r.stderr and "installed" in r.stderr, f"no sbatch: {r.returncode}: {r.stderr}")
    check("--array=1-2" in open(os.path.join(out, "slurm", "sweep.sbatch")).read(), "no job script")


def interrupt_when(out, jobs, end_times, ready):
    """Starts a sweep over end times, sends SIGINT once every path in `ready` exists, returns stderr.
    The spheres are at rest, so a long run can only end by reaching its end time."""
    p = subprocess.Popen([FIRN, "sweep", SCENE, "--preview", "--out", out, "--jobs", str(jobs),
                          "--set", "bodies.0.velocity=[0,0,0]", "--set", "bodies.1.velocity=[0,0,0]",
                          "--vary", "simulation.end_time=" + end_times], stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while not all(os.path.exists(os.path.join(out, path)) for path in ready) and time.time() < deadline:
        time.sleep(0.05)
    p.send_signal(signal.SIGINT)
    err = p.communicate(timeout=120)[1]
    check(p.returncode == 130, f"exit status {p.returncode} after SIGINT: {err}")
    return err


def test_interrupt():
    # One at a time: the first run finishes, the second is stopped, the third never starts.
    out = fresh("interrupt")
    interrupt_when(out, 1, "0.1,1e6,1e6", ["sweep.csv", "runs/002_1e6/particles/00001.vtp"])
    rows = table(out)[1:]
    check([row[:2] for row in rows] == [["0.1", "ok"]], f"sweep.csv after SIGINT: {rows}")
    check(summary(os.path.join(out, "runs", "002_1e6"))["status"] == "interrupted", "the child was not stopped")
    check(not os.path.exists(os.path.join(out, "runs", "003_1e6")), "a run was started after SIGINT")
    # Two at a time, none finished: both stopped, sweep.csv has its header only.
    out = fresh("interrupt_none")
    interrupt_when(out, 2, "1e6,2e6", ["runs/001_1e6/particles/00001.vtp", "runs/002_2e6/particles/00001.vtp"])
    check(table(out) == [["simulation.end_time"] + RUN_COLUMNS], f"sweep.csv: {table(out)}")
    for run in ["001_1e6", "002_2e6"]:
        check(summary(os.path.join(out, "runs", run))["status"] == "interrupted", f"{run} was not stopped")


PAIR = os.path.join(ROOT, "scenes", "snowball_pair.toml")


def pair_sweep(out, *args):
    """Two snowball_pair runs (about 2 s each), one at a time."""
    return [FIRN, "sweep", PAIR, "--preview", "--out", out, "--jobs", "1", "--set", "simulation.end_time=20 ms",
            "--vary", "simulation.cfl=0.4,0.3"] + list(args)


def test_resume():
    # A sweep killed with SIGKILL (the sweep and its runs at once) while its second run is part way
    # and resumed with --resume ends with the runs of an uninterrupted sweep: the first run kept,
    # the second resumed from its checkpoint, the same state hashes.
    whole = fresh("resume_whole")
    r = subprocess.run(pair_sweep(whole), capture_output=True, text=True, timeout=300)
    check(r.returncode == 0, f"uninterrupted sweep: {r.returncode}: {r.stderr}")
    out = fresh("resume")
    p = subprocess.Popen(pair_sweep(out, "--checkpoint-every", "4 ms"), stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    runs = lambda d: sorted(glob.glob(os.path.join(d, "runs", "*")))
    deadline = time.time() + 300
    while time.time() < deadline and p.poll() is None:
        r = runs(out)
        if len(r) == 2 and os.path.exists(os.path.join(r[0], "summary.json")) and \
                os.path.exists(os.path.join(r[1], "checkpoint.firn")):
            break
        time.sleep(0.02)
    check(p.poll() is None, "the sweep ended before it was killed")
    os.killpg(p.pid, signal.SIGKILL)
    p.communicate(timeout=60)
    check(not os.path.exists(os.path.join(runs(out)[1], "summary.json")), "the second run had finished")
    r = subprocess.run([FIRN, "sweep", "--resume", out], capture_output=True, text=True, timeout=300)
    check(r.returncode == 0 and "1 finished before, 1 to resume or run" in r.stderr, f"--resume: {r.returncode}: {r.stderr}")
    for a, b in zip(runs(out), runs(whole)):
        sa, sb = summary(a), summary(b)
        check(sa["state_hash"] == sb["state_hash"] and sa["steps"] == sb["steps"],
              f"{a}: {sa['state_hash']} after {sa['steps']} steps, uninterrupted {sb['state_hash']} after {sb['steps']}")
    check([row[:2] for row in table(out)] == [row[:2] for row in table(whole)], f"sweep.csv: {table(out)}")
    r = subprocess.run([FIRN, "sweep", "--resume", out, PAIR], capture_output=True, text=True, timeout=60)
    check(r.returncode == 2, f"--resume with a scene: {r.returncode}: {r.stderr}")


os.makedirs(SCRATCH, exist_ok=True)
globals()["test_" + TEST]()
print("ok")
