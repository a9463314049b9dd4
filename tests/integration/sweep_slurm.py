#!/usr/bin/python3
"""sweep_slurm: `dream sweep --engine slurm` against a real one-node Slurm cluster (issue 26).

The test starts its own cluster (slurm_cluster.py: munged, slurmctld, slurmd, a private
slurm.conf, inside the private network namespace netns.sh makes) and stops every daemon it
started, also when a check fails. It shows:
1. A 40-run sweep (20 seeds x 2 speeds, C++ controller) through one job array and the
   `afterany` table job gives the local engine's table, timings aside; `dream sweep status` counts
   40 finished.
2. A Python controller's sweep (its module copied into each run folder) through Slurm, one task
   at a time: `scancel` of the array while a task runs leaves a "cancelled in Slurm" row and
   "never started" rows (the table job still writes the table); `dream sweep resume` submits only
   those, and the table then equals the local engine's.
3. A node-side failure: the dream binary the tasks run is gone when they start (exit 127); every
   run is a "failed to run (exit 127: ... not found)" row; resume with an installed dream completes it.
4. Issue 34: a sweep folder whose name holds '%' (and Slurm's own %A, %j): sbatch gets it quoted
   (%%), so the tasks' logs and the table land in that folder and every run finishes; a folder
   holding a backslash (which turns sbatch's symbols off) is refused before anything is submitted.
Skipped (exit 77) when not root or slurm-wlm / munge are missing.

Usage: sweep_slurm.py --dream BIN --source DIR
"""

import csv
import io
import os
import shutil
import subprocess
import sys
import tempfile
import time

from dreamtest import arguments, check, fail, main
from slurm_cluster import SlurmCluster, missing_requirements


def read(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path) as f:
        return f.read()


def rows_without_timing(out):
    """sweep.csv's rows by run, without wall_time_s."""
    rows = {}
    for row in csv.DictReader(io.StringIO(read(os.path.join(out, "sweep.csv")))):
        row.pop("wall_time_s")
        rows[row["run"]] = row
    return rows


def run_rows(out):
    """sweep.md's table of runs (the lines after '## Runs')."""
    text = read(os.path.join(out, "sweep.md"))
    check("## Runs" in text, f"{out}/sweep.md has no '## Runs' table")
    return [line for line in text.split("## Runs", 1)[1].splitlines() if line.startswith("| seed")]


def dream(cluster, args, *words, timeout=120):
    return cluster.run([args.dream, *words], timeout=timeout)


def wait_for_table(cluster, out, timeout):
    """Waits until the sweep's jobs (the array and the table job) have left the queue."""
    if not cluster.wait_empty(timeout):
        fail(f"Slurm jobs still queued after {timeout} s: {cluster.queue()[:10]}")
    check(os.path.isfile(os.path.join(out, "sweep.md")), f"the table job wrote no {out}/sweep.md: "
          f"{[read(os.path.join(out, 'slurm', n))[-300:] for n in os.listdir(os.path.join(out, 'slurm')) if n.startswith('table')]}")


def same_sweep(cluster, args, work):
    config = os.path.join(args.source, "config", "hrvo_circle.yaml")
    words = [config, "--seeds", "1-20", "--set", "controller.max_speed_mps=0.1,0.2", "--steps", "30", "--jobs", "2"]
    local, slurm = os.path.join(work, "local"), os.path.join(work, "slurm")
    code, text = dream(cluster, args, "-q", "sweep", *words, "--out", local)
    check(code == 0, f"local sweep exited {code}: {text[-500:]}")
    started = time.monotonic()
    code, text = dream(cluster, args, "sweep", *words, "--out", slurm, "--engine", "slurm")
    check(code == 0 and "submitted 40 runs to Slurm" in text, f"slurm sweep exited {code}: {text[-500:]}")
    wait_for_table(cluster, slurm, 180)
    elapsed = time.monotonic() - started
    a, b = rows_without_timing(local), rows_without_timing(slurm)
    check(len(a) == 40 and a == b, f"the Slurm table differs from the local one: "
          f"{[(k, a.get(k), b.get(k)) for k in sorted(set(a) | set(b)) if a.get(k) != b.get(k)][:2]}")
    check(run_rows(local) == run_rows(slurm), "sweep.md's run rows differ between local and Slurm")
    check("## By value" in read(os.path.join(slurm, "sweep.md")), "sweep.md has no per-value figures")
    code, text = dream(cluster, args, "sweep", "status", slurm)
    check(code == 0 and "finished     40" in text, f"dream sweep status: {text}")
    return f"40 runs through Slurm in {elapsed:.1f} s: the local table, row for row"


def cancel_and_resume(cluster, args, work):
    config = os.path.join(args.source, "config", "go_to_goal_python.yaml")
    # Runs of a second or two (so scancel meets one running), and an agent timeout no load on the
    # test machine can reach (a Python agent marked lost would change the run, not the engine).
    words = [config, "--seeds", "1-3", "--set", "controller.max_speed_mps=0.1,0.2", "--set", "world.agent_timeout_s=60",
             "--steps", "200"]
    local, slurm = os.path.join(work, "py_local"), os.path.join(work, "py_slurm")
    code, text = dream(cluster, args, "-q", "sweep", *words, "--jobs", "2", "--out", local)
    check(code == 0, f"local Python sweep exited {code}: {text[-500:]}")
    code, text = dream(cluster, args, "sweep", *words, "--jobs", "1", "--out", slurm, "--engine", "slurm")
    check(code == 0, f"Python slurm sweep exited {code}: {text[-500:]}")
    with open(os.path.join(slurm, "slurm", "jobs.txt")) as f:
        array = next(line.split()[1] for line in f if line.startswith("array"))
    # Wait until one run has finished and the next one's dream run has started (its output.txt, no
    # exit.txt: squeue says RUNNING before the task's script even starts), then cancel the array.
    deadline = time.monotonic() + 60
    runs = os.path.join(slurm, "runs")
    while time.monotonic() < deadline:
        finished = [n for n in os.listdir(runs) if os.path.exists(os.path.join(runs, n, "exit.txt"))]
        started = [n for n in os.listdir(runs) if os.path.exists(os.path.join(runs, n, "output.txt"))
                   and not os.path.exists(os.path.join(runs, n, "exit.txt"))]
        if finished and started and any(s.endswith("|RUNNING") and s.startswith(array + "_") for s in cluster.queue()):
            break
        time.sleep(0.05)
    else:
        fail(f"no run finished with the next one running within 60 s: {cluster.queue()}")
    code, text = cluster.run(["scancel", array])
    check(code == 0, f"scancel {array}: {text}")
    wait_for_table(cluster, slurm, 60)
    md = read(os.path.join(slurm, "sweep.md"))
    check("failed to run (cancelled in Slurm" in md, f"no 'cancelled in Slurm' row after scancel: {md[-1500:]}")
    check("not run (never started)" in md, f"no 'never started' row after scancel: {md[-1500:]}")
    code, text = dream(cluster, args, "sweep", "status", slurm)
    check(code == 0 and "cancelled in Slurm" in text and "dream sweep resume" in text, f"status after scancel: {text}")
    code, text = dream(cluster, args, "sweep", "resume", slurm)
    check(code == 0 and "submitted" in text, f"resume exited {code}: {text[-500:]}")
    wait_for_table(cluster, slurm, 120)
    check(rows_without_timing(local) == rows_without_timing(slurm),
          f"after resume the Slurm table differs from the local one: {read(os.path.join(slurm, 'sweep.md'))[-1500:]}")
    for name in os.listdir(os.path.join(slurm, "runs")):
        check(os.path.isfile(os.path.join(slurm, "runs", name, "python", "go_to_goal.py")),
              f"run {name} has no copy of its Python module")
    return f"scancel of array {array} left cancelled and never-started rows; resume completed the local table"


def node_failure(cluster, args, work):
    # A dream binary that is gone when the tasks start: the job is held, the copy removed, then released.
    bin_dir = os.path.join(work, "vanishing")
    os.makedirs(bin_dir)
    copy = os.path.join(bin_dir, "dream")
    shutil.copy2(args.dream, copy)
    out = os.path.join(work, "gone")
    config = os.path.join(args.source, "config", "hrvo_circle.yaml")
    code, text = cluster.run([copy, "sweep", config, "--seeds", "1-2", "--steps", "30", "--out", out, "--engine",
                              "slurm", "--slurm-option=--hold"])
    check(code == 0, f"held sweep exited {code}: {text[-500:]}")
    os.remove(copy)
    with open(os.path.join(out, "slurm", "jobs.txt")) as f:
        jobs = [line.split()[1] for line in f if line.startswith(("array", "table"))]
    code, text = cluster.run(["scontrol", "release", ",".join(jobs)])
    check(code == 0, f"scontrol release: {text}")
    if not cluster.wait_empty(60):
        fail(f"jobs still queued: {cluster.queue()}")
    code, text = dream(cluster, args, "sweep", "table", out)
    check(code == 4, f"dream sweep table of failed runs exited {code}, expected 4: {text[-500:]}")
    md = read(os.path.join(out, "sweep.md"))
    check(md.count("failed to run (exit 127:") == 2 and "not found" in md,
          f"expected two 'failed to run (exit 127: ... not found)' rows: {md[-1200:]}")
    # The sweep's own --slurm-option (--hold) would hold the new jobs too: resume replaces it.
    code, text = dream(cluster, args, "sweep", "resume", out, "--slurm-option=--partition=debug")
    check(code == 0, f"resume with an installed dream exited {code}: {text[-500:]}")
    wait_for_table(cluster, out, 60)
    code, text = dream(cluster, args, "sweep", "table", out)
    check(code == 0 and "2 ran, 0 failed" in text, f"after resume: {text[-600:]}")
    return "a missing dream on the node is an 'exit 127: ... not found' row; resume completes the sweep"


def percent_folder(cluster, args, work):
    out = os.path.join(work, "100% of %A_%j")
    config = os.path.join(args.source, "config", "hrvo_circle.yaml")
    code, text = dream(cluster, args, "sweep", config, "--seeds", "1-2", "--steps", "30", "--out", out, "--engine", "slurm")
    check(code == 0, f"sweep into {out!r} exited {code}: {text[-500:]}")
    wait_for_table(cluster, out, 120)
    with open(os.path.join(out, "slurm", "jobs.txt")) as f:
        array = next(line.split()[1] for line in f if line.startswith("array"))
    logs = sorted(n for n in os.listdir(os.path.join(out, "slurm")) if n.endswith(".out"))
    check(f"{array}_0.out" in logs and f"{array}_1.out" in logs and any(n.startswith("table_") for n in logs),
          f"the tasks' logs are not in {out}/slurm: {logs}")
    code, text = dream(cluster, args, "sweep", "status", out)
    check(code == 0 and "finished     2" in text, f"status of the '%' sweep: {text}")
    backslash = os.path.join(work, "back\\slash")
    code, text = dream(cluster, args, "sweep", config, "--seeds", "1", "--out", backslash, "--engine", "slurm")
    check(code == 1 and "backslash" in text and not os.path.exists(backslash), f"--out with a backslash exited {code}: {text}")
    return "a folder named '100% of %A_%j': logs and table in it, 2 finished; a backslash refused"


def test(ctx, args):
    work = ctx.path("work")
    os.makedirs(work)
    folder = tempfile.mkdtemp(prefix="dream_slurm_")
    try:
        cluster = SlurmCluster(folder)  # stops what it started when it fails
    except BaseException:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    try:
        for part in (same_sweep, cancel_and_resume, node_failure, percent_folder):
            started = time.monotonic()
            print(f"{part(cluster, args, work)} ({time.monotonic() - started:.1f} s)", flush=True)
    finally:
        cluster.stop()
        if os.environ.get("DREAM_TEST_KEEP") != "1":
            shutil.rmtree(cluster.folder, ignore_errors=True)


def private_network():
    """Re-runs this script in a private network namespace (once): loopback, plus a veth pair
    whose both ends stay inside it, because Slurm's daemons bind their ports with getaddrinfo's
    AI_ADDRCONFIG, which finds no address when loopback is the only interface. Nothing the
    daemons send can leave the namespace."""
    if os.environ.get("DREAM_SLURM_NETNS") == "1":
        for command in (["ip", "link", "set", "lo", "up"],
                        ["ip", "link", "add", "dreamslurm0", "type", "veth", "peer", "name", "dreamslurm1"],
                        ["ip", "addr", "add", "10.254.254.1/32", "dev", "dreamslurm0"],
                        ["ip", "link", "set", "dreamslurm0", "up"], ["ip", "link", "set", "dreamslurm1", "up"]):
            subprocess.run(command, check=True)
        return
    if subprocess.run(["unshare", "-n", "true"], stderr=subprocess.DEVNULL).returncode != 0:
        print("SKIP: cannot create a private network namespace (unshare -n)")
        sys.exit(77)
    os.environ["DREAM_SLURM_NETNS"] = "1"
    os.execvp("unshare", ["unshare", "-n", sys.executable] + sys.argv)


if __name__ == "__main__":
    why = missing_requirements()
    if why:
        print(f"SKIP: {why}")
        sys.exit(77)
    args = arguments()
    private_network()
    main(lambda ctx: test(ctx, args))
