"""firn sweep --scheduler slurm on a real one-node Slurm (issue 20, item 6).

Usage: python3 slurm_test.py FIRN REPO_ROOT SCRATCH_DIR array
Installs Debian's Slurm and munge when they are missing (as root, with apt-get), starts munged if no
munge daemon answers, and starts slurmctld and slurmd on this machine with a configuration of its
own (127.0.0.1, ports 16817-16818, state under SCRATCH_DIR; SLURM_CONF points sbatch and squeue at
it). Then a 2x2 sweep of the tiny two_spheres scene is submitted as a job array, waited for with
squeue, and collected with firn sweep --collect: four ok rows in sweep.csv, each run with its own
values. Exits with status 77 (skipped, with the reason) when Slurm cannot be installed or started.
"""
import csv
import os
import re
import shutil
import socket
import subprocess
import sys
import time

from end_to_end import FIRN, ROOT, SCRATCH, TEST, check, fresh

DAEMONS = ["slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "munged", "munge"]


def skip(reason):
    print("SKIPPED: Slurm test: " + reason)
    sys.exit(77)


def run(*args, **kw):
    return subprocess.run(list(args), capture_output=True, text=True, timeout=kw.pop("timeout", 60), **kw)


def install():
    if all(shutil.which(d) for d in DAEMONS):
        return
    if os.geteuid() != 0 or not shutil.which("apt-get"):
        skip("Slurm is not installed and this is not root with apt-get (make slurm-deps installs it)")
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    run("apt-get", "update", "-q", timeout=600)
    r = run("apt-get", "install", "-y", "-q", "--no-install-recommends", "slurmctld", "slurmd", "slurm-client",
            "munge", env=env, timeout=900)
    if r.returncode != 0:
        skip("apt-get install of slurm and munge failed: " + r.stderr.strip()[-300:])


def munge_works():
    enc = run("munge", "-n")
    return enc.returncode == 0 and run("unmunge", input=enc.stdout).returncode == 0


def start_munge():
    if munge_works():
        return
    if not os.path.exists("/etc/munge/munge.key"):
        run("mungekey", "--create")
        shutil.chown("/etc/munge/munge.key", "munge", "munge")
        os.chmod("/etc/munge/munge.key", 0o400)
    os.makedirs("/run/munge", exist_ok=True)
    shutil.chown("/run/munge", "munge", "munge")
    r = run("runuser", "-u", "munge", "--", "munged")
    if not munge_works():
        skip("munged does not start: " + r.stderr.strip())


def write_config(base):
    host = socket.gethostname().split(".")[0]
    cpus = os.cpu_count() or 1
    for d in ["state", "spool"]:
        os.makedirs(os.path.join(base, d))
    conf = os.path.join(base, "slurm.conf")
    with open(conf, "w") as f:
        f.write(f"""ClusterName=firntest
SlurmctldHost={host}(127.0.0.1)
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
AuthType=auth/munge
StateSaveLocation={base}/state
SlurmdSpoolDir={base}/spool
SlurmctldPidFile={base}/slurmctld.pid
SlurmdPidFile={base}/slurmd.pid
SlurmctldLogFile={base}/slurmctld.log
SlurmdLogFile={base}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
NodeName={host} NodeAddr=127.0.0.1 CPUs={cpus} State=UNKNOWN
PartitionName=firn Nodes={host} Default=YES MaxTime=INFINITE State=UP
""")
    return conf


def start_slurm(base, env):
    conf = write_config(base)
    env["SLURM_CONF"] = conf
    daemons = [subprocess.Popen([d, "-D", "-f", conf], env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
               for d in ["slurmctld", "slurmd"]]
    for _ in range(60):
        r = run("sinfo", "-h", "-o", "%t", env=env)
        if r.returncode == 0 and r.stdout.strip() in ("idle", "mix", "alloc"):
            return daemons
        time.sleep(1)
    stop(daemons)
    logs = ""
    for name in ["slurmctld.log", "slurmd.log"]:
        path = os.path.join(base, name)
        if os.path.exists(path):
            logs += name + ": " + open(path).read().strip()[-400:] + "\n"
    skip("slurmctld and slurmd did not bring the node up within 60 s\n" + logs)


def stop(daemons):
    for d in daemons:
        d.terminate()
    for d in daemons:
        try:
            d.wait(timeout=30)
        except subprocess.TimeoutExpired:
            d.kill()


check(TEST == "array", "unknown test " + TEST)
install()
start_munge()
base = fresh("slurm")
os.makedirs(base)
env = dict(os.environ)
daemons = start_slurm(base, env)
try:
    out = os.path.join(base, "sweep")
    r = run(FIRN, "sweep", os.path.join(ROOT, "scenes", "two_spheres.toml"), "--preview", "--scheduler", "slurm",
            "--out", out, "--set", "simulation.end_time=0.02", "--vary", "simulation.cfl=0.3,0.4",
            "--vary", "bodies.0.velocity=[0.1, 0, 0],[0.2, 0, 0]", "--sbatch=--cpus-per-task=1", env=env)
    check(r.returncode == 0, "firn sweep --scheduler slurm failed: " + r.stderr)
    script = open(os.path.join(out, "slurm", "sweep.sbatch")).read()
    check("#SBATCH --array=1-4\n" in script and "#SBATCH --cpus-per-task=1\n" in script,
          "the job script lacks its array or sbatch lines:\n" + script)
    job = r.stderr.split("job array ")[1].split()[0]
    for _ in range(600):
        q = run("squeue", "-h", "-j", job, env=env)
        if q.returncode == 0 and not q.stdout.strip():
            break
        time.sleep(1)
    else:
        check(False, "job array " + job + " still queued or running after 10 minutes")
    r = run(FIRN, "sweep", "--collect", out, env=env)
    check(r.returncode == 0, "firn sweep --collect failed: " + r.stderr)
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 4 and all(row["status"] == "ok" for row in rows), "sweep.csv: %r" % rows)
    check([(row["simulation.cfl"], row["bodies.0.velocity"]) for row in rows] ==
          [(c, v) for c in ["0.3", "0.4"] for v in ["[0.1, 0, 0]", "[0.2, 0, 0]"]], "rows out of order: %r" % rows)
    for task, run_dir in enumerate(sorted(os.listdir(os.path.join(out, "runs"))), 1):
        cfl = 0.3 if task <= 2 else 0.4
        resolved = open(os.path.join(out, "runs", run_dir, "scene.resolved.toml")).read()
        got = re.search(r"^cfl = (\S+)$", resolved, re.M)
        check(got and abs(float(got.group(1)) - cfl) < 1e-12, run_dir + " did not run with cfl %g" % cfl)
        check(os.path.exists(os.path.join(out, "slurm", "task_%d.txt" % task)), "Slurm ran no task %d" % task)
    print("ok: job array %s, 4 runs collected" % job)
finally:
    stop(daemons)
