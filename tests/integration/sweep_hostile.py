#!/usr/bin/python3
"""sweep_hostile: issue 34's attacks on sweep folders, with real processes (dream and sh run.sh).

1. FIFOs as a run folder's exit.txt, summary.json and output.txt: `dream sweep table` and
   `status` return at once (no read waits on a FIFO), the runs are failed rows naming why.
2. An --engine plan run still running (`sh run.sh 0` from commands.txt): `status` says running,
   not killed; `resume` runs the other run and leaves it alone (its log keeps growing); a second
   `sh run.sh 0` refuses it; once it is killed, status calls it killed before it ended.
3. plan.tsv edited to name a run ../../victim: `sh run.sh` refuses (the plan's SHA-256 is in
   run.sh), and with run.sh's digest forged too, refuses the name; resume refuses the edited
   plan; a run folder replaced by a link to another run: run.sh and resume refuse it, the other
   run is untouched.
4. The base config edited before resume: refused naming it; `sha256sum -c inputs.sha256` tells the
   same. --out holding a newline is refused; one holding spaces, quotes and $ runs from
   commands.txt line by line.

Usage: sweep_hostile.py --dream BIN --source DIR
"""

import fcntl
import hashlib
import os
import re
import shutil
import subprocess
import time

from dreamtest import arguments, check, main

EXIT_INPUT = 1
EXIT_RUN_FAILED = 4


def read_text(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path) as f:
        return f.read()


def write_text(path, text):
    with open(path, "w") as f:
        f.write(text)


def fifo_files(ctx, dream, config):
    out = ctx.path("fifos")
    ctx.run([dream, "-q", "sweep", config, "--seeds", "1-3", "--steps", "40", "--jobs", "2", "--out", out],
            timeout=60, expect=0)
    runs = os.path.join(out, "runs")
    for seed, name in ((1, "exit.txt"), (2, "summary.json"), (3, "output.txt")):
        os.remove(os.path.join(runs, f"seed{seed}", name))
        os.mkfifo(os.path.join(runs, f"seed{seed}", name))
    write_text(os.path.join(runs, "seed3", "exit.txt"), "4 0.5 0\n")  # a failed run: its output.txt is read
    started = time.monotonic()
    code, text = ctx.run([dream, "sweep", "table", out], timeout=30)
    check(code == EXIT_RUN_FAILED, f"dream sweep table exited {code}, expected 4: {text[-500:]}")
    md = read_text(os.path.join(out, "sweep.md"))
    check("no readable exit record" in md and "exit.txt" in md, f"no row naming seed1's exit.txt: {md[-1500:]}")
    code, text = ctx.run([dream, "sweep", "status", out], timeout=30, expect=0)
    check(re.search(r"failed\s+3", text), f"status of the FIFO runs: {text}")
    return f"FIFOs as exit.txt, summary.json, output.txt: table and status in {time.monotonic() - started:.1f} s, 3 failed rows"


def long_config(ctx, config):
    """go_to_goal that runs every step of its limit."""
    text, count = re.subn(r"^stop_when_done:\s*\S+", "stop_when_done: false", read_text(config), count=1,
                          flags=re.MULTILINE)
    check(count == 1, "internal: no stop_when_done line")
    path = ctx.path("long.yaml")
    write_text(path, text)
    return path


def wait_for(what, condition, proc, timeout=60):
    deadline = time.monotonic() + timeout
    while not condition():
        check(proc.poll() is None, f"{what}: the run ended first (exit {proc.returncode})")
        check(time.monotonic() < deadline, f"{what}: not within {timeout} s")
        time.sleep(0.05)


def plan_run_still_running(ctx, dream, config):
    out = ctx.path("plan_running")
    # Run 0 never ends by itself; run 1 is 40 steps.
    ctx.run([dream, "sweep", long_config(ctx, config), "--set", "steps=100000000,40", "--engine", "plan",
             "--out", out], timeout=60, expect=0)
    lines = read_text(os.path.join(out, "commands.txt")).splitlines()
    check(len(lines) == 2, f"commands.txt: {lines}")
    busy = os.path.join(out, "runs", "seed1_steps-100000000")
    log = os.path.join(busy, "run.lcmlog.part")
    task = ctx.start("task0", ["sh", "-c", lines[0]], own_group=True)
    wait_for("run 0's log", lambda: os.path.exists(log) and os.path.getsize(log) > 0, task)

    code, text = ctx.run([dream, "sweep", "status", out], timeout=30, expect=0)
    check(re.search(r"running\s+1", text) and "killed" not in text, f"status of a running plan run: {text}")
    code, text = ctx.run([dream, "sweep", "resume", out], timeout=60)
    check(code == EXIT_RUN_FAILED and "still running" in text, f"resume beside a running run exited {code}: {text[-600:]}")
    check(task.poll() is None and os.path.exists(log), "resume touched the running run")
    size = os.path.getsize(log)
    wait_for("run 0's log growing after resume", lambda: os.path.getsize(log) > size, task)
    check(os.path.isfile(os.path.join(out, "runs", "seed1_steps-40", "exit.txt")), "resume did not run run 1")
    check("running (its dream run holds" in read_text(os.path.join(out, "sweep.md")), "the table does not say running")
    code, text = ctx.run(["sh", os.path.join(out, "run.sh"), "0"], timeout=60)
    check(code == 75 and "still running" in text, f"a second sh run.sh 0 exited {code}: {text}")
    check(task.poll() is None, "the second run.sh disturbed the first")

    ctx.stop("task0")  # killed: no exit record is written, and the lock goes with its processes
    with open(os.path.join(busy, ".dream.lock")) as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)  # waits until the last of them has exited
    code, text = ctx.run([dream, "sweep", "status", out], timeout=30, expect=0)
    check(re.search(r"running\s+0", text) and "killed before it ended" in text, f"status after the kill: {text}")
    return "a running plan run: status 'running', resume ran the other and left it alone, a second run.sh refused"


def edited_plan_and_links(ctx, dream, config):
    out = ctx.path("plan_edit")
    ctx.run([dream, "sweep", config, "--seeds", "1-2", "--steps", "40", "--engine", "plan", "--out", out],
            timeout=60, expect=0)
    run_sh = os.path.join(out, "run.sh")
    code, text = ctx.run(["sh", run_sh, "0"], timeout=60)  # 40 steps: dream run's exit 5, goal not reached yet
    check(os.path.isfile(os.path.join(out, "runs", "seed1", "exit.txt")), f"sh run.sh 0 exited {code}: {text}")
    victim = ctx.path("victim")
    os.makedirs(victim)
    write_text(os.path.join(victim, "summary.json"), "precious")
    plan_path = os.path.join(out, "plan.tsv")
    plan = read_text(plan_path)
    write_text(plan_path, plan.replace("\tseed2\t", "\t../../victim\t"))
    code, text = ctx.run(["sh", run_sh, "1"], timeout=30)
    check(code == 2 and "changed since the sweep was planned" in text, f"run.sh with an edited plan exited {code}: {text}")
    # An attacker who also forges the digest in run.sh: the name itself is refused.
    digest = hashlib.sha256(read_text(plan_path).encode()).hexdigest()
    script = read_text(run_sh)
    write_text(run_sh, re.sub(r"^plan_sha256=\w+$", f"plan_sha256={digest}", read_text(run_sh), flags=re.MULTILINE))
    code, text = ctx.run(["sh", run_sh, "1"], timeout=30)
    check(code == 2 and "no run folder name" in text, f"run.sh with ../../victim exited {code}: {text}")
    check(os.listdir(victim) == ["summary.json"] and read_text(os.path.join(victim, "summary.json")) == "precious",
          f"the victim folder was touched: {os.listdir(victim)}")
    code, text = ctx.run([dream, "sweep", "resume", out], timeout=30)
    check(code == EXIT_INPUT and "plan.tsv" in text and "victim" in text, f"resume of an edited plan exited {code}: {text[-400:]}")
    check(os.listdir(victim) == ["summary.json"], f"resume touched the victim folder: {os.listdir(victim)}")
    write_text(plan_path, plan)
    write_text(run_sh, script)

    # Run 1's folder replaced by a link to run 0's.
    seed1, seed2 = os.path.join(out, "runs", "seed1"), os.path.join(out, "runs", "seed2")
    before = {name: read_text(os.path.join(seed1, name)) for name in ("exit.txt", "summary.json")}
    shutil.rmtree(seed2)
    os.symlink(seed1, seed2)
    code, text = ctx.run([dream, "sweep", "resume", out], timeout=30)
    check(code == EXIT_INPUT and "is a symbolic link" in text, f"resume through a linked run folder exited {code}: {text[-400:]}")
    code, text = ctx.run(["sh", run_sh, "1"], timeout=30)
    check(code == 2 and "symbolic link" in text, f"run.sh through a linked run folder exited {code}: {text}")
    after = {name: read_text(os.path.join(seed1, name)) for name in ("exit.txt", "summary.json")}
    check(before == after, "the run behind the link was rewritten")
    return "../../victim refused by run.sh (digest, then name) and resume; a linked run folder refused, its target untouched"


def inputs_and_names(ctx, dream, config):
    base = ctx.path("base.yaml")
    shutil.copy(config, base)
    out = ctx.path("it's a $HOME sweep")
    ctx.run([dream, "sweep", base, "--seeds", "1-2", "--steps", "40", "--engine", "plan", "--out", out], timeout=60,
            expect=0)
    lines = read_text(os.path.join(out, "commands.txt")).splitlines()
    check(len(lines) == 2, f"commands.txt of a folder with spaces and quotes: {lines}")
    for line in lines:
        ctx.run(["sh", "-c", line], timeout=60)
    ctx.run([dream, "sweep", "table", out], timeout=30, expect=0)
    result = subprocess.run(["sha256sum", "-c", "inputs.sha256"], cwd=out, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    check(result.returncode == 0, f"sha256sum -c inputs.sha256 of a fresh sweep: {result.stdout}")
    write_text(base, read_text(base).replace("max_speed_mps: 0.15", "max_speed_mps: 0.12", 1))
    os.remove(os.path.join(out, "runs", "seed2", "exit.txt"))
    code, text = ctx.run([dream, "sweep", "resume", out], timeout=30)
    check(code == EXIT_INPUT and f"the base config {base}" in text and "changed since the sweep was planned" in text,
          f"resume after the base config changed exited {code}: {text[-400:]}")
    result = subprocess.run(["sha256sum", "-c", "inputs.sha256"], cwd=out, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    check(result.returncode != 0 and "FAILED" in result.stdout, f"sha256sum -c after the edit: {result.stdout}")

    newline = ctx.path("two\nlines")
    code, text = ctx.run([dream, "sweep", config, "--seeds", "1-2", "--engine", "plan", "--out", newline], timeout=30)
    check(code == EXIT_INPUT and "control character" in text and not os.path.exists(newline),
          f"--out with a newline exited {code}: {text[-400:]}")
    return "an edited base config refused by resume (and by sha256sum -c); --out with a newline refused; quotes and $ run"


def test(ctx):
    args = arguments()
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    for part in (fifo_files, plan_run_still_running, edited_plan_and_links, inputs_and_names):
        started = time.monotonic()
        print(f"{part(ctx, args.dream, config)} ({time.monotonic() - started:.1f} s)", flush=True)


if __name__ == "__main__":
    main(test)
