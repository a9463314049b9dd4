#!/usr/bin/python3
"""folders_and_children: an output folder is locked while a run writes it, children die with their
parent, and too few file descriptors are reported at once (issue 10 item 4).

In a private network namespace:
  - a realtime `dream launch --out X` (its simulator inherits the folder's lock) is running: a
    `dream run --out X`, a `dream run --out X --overwrite` and a `dream launch --out X` are each
    refused within seconds, exit 1, naming the launch's pid and command line; the launch then ends
    normally with its own log;
  - two `dream run`s without --out in one folder: the second, started while the first writes
    runs/<name>, goes to runs/<name>_2;
  - SIGKILL of a `dream launch` (simulator + 8 agents) and of a `dream sweep` (2 `dream run`s at
    once): within 5 s none of their children is left (a zombie waiting for its reaper is gone), and
    the launch's simulator, stopped by SIGTERM, still wrote its summary ("interrupted");
  - `ulimit -n 8` under `dream launch`: exit 1 within 5 s, "too few file descriptors: limit 8,
    need about 24 per process; raise with ulimit -n 24" (it used to stall 90 s).

Usage: netns.sh folders_and_children.py --dream BIN --source DIR
"""

import os
import re
import signal
import subprocess
import time

from dreamtest import arguments, check, main, read_summary, require_private_netns, tail

KILL_BOUND_S = 5.0


def children_of(pid):
    """The pids of pid's children (every thread's), from /proc."""
    found = set()
    try:
        for task in os.listdir(f"/proc/{pid}/task"):
            with open(f"/proc/{pid}/task/{task}/children") as f:
                found.update(int(child) for child in f.read().split())
    except FileNotFoundError:
        pass
    return found


def alive(pid):
    """True while pid exists and is not a zombie."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            state = f.read().rsplit(")", 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return False
    return state != "Z"


def wait_for_children(pid, count, timeout):
    """pid's children once there are at least `count` of them."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        children = children_of(pid)
        if len(children) >= count:
            return children
        time.sleep(0.05)
    check(False, f"process {pid} did not start {count} children within {timeout} s (has {children_of(pid)})")


def expect_none_left(children, what):
    deadline = time.monotonic() + KILL_BOUND_S
    while time.monotonic() < deadline and any(alive(child) for child in children):
        time.sleep(0.05)
    left = [child for child in children if alive(child)]
    check(not left, f"{len(left)} of {len(children)} children of the SIGKILLed {what} still run "
                    f"{KILL_BOUND_S} s later: {left}")


def test(ctx):
    args = arguments()
    require_private_netns()
    dream = args.dream
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    os.chdir(ctx.dir)

    # --- a folder written by a launch is refused to every other writer ---
    out = ctx.path("busy")
    launch = ctx.start("launch", [dream, "launch", config, "--out", out, "--mode", "realtime", "--steps", "150"])
    wait_for_children(launch.pid, 9, 10)
    ctx.wait_for_output("launch", r"launched the simulator", 10)
    for name, argv in [("run", [dream, "run", config, "--out", out, "--steps", "5"]),
                       ("overwrite", [dream, "run", config, "--out", out, "--steps", "5", "--overwrite"]),
                       ("launch", [dream, "launch", config, "--out", out, "--steps", "5"])]:
        started = time.monotonic()
        code, output = ctx.run(argv, timeout=10)
        check(code == 1, f"a second {name} into a folder being written exited {code}: {tail(output)}")
        check(time.monotonic() - started < 5, f"the second {name} took {time.monotonic() - started:.1f} s to refuse")
        pattern = rf"output folder {re.escape(out)} is being written by pid {launch.pid} \(.*dream launch "
        check(re.search(pattern, output), f"the second {name} does not name the launch: {tail(output)}")
    code = ctx.wait("launch", 60)
    check(code not in (1, 2) and code < 128, f"the launch failed ({code}): {tail(ctx.output('launch'))}")
    check(os.path.isfile(os.path.join(out, "run.lcmlog")), "the launch wrote no run.lcmlog")

    # --- default folders: a run being written is skipped like a finished one ---
    ctx.start("first", [dream, "run", config, "--mode", "realtime", "--steps", "120"])
    deadline = time.monotonic() + 10
    while not os.path.exists(os.path.join("runs", "go_to_goal", ".dream.lock")) and time.monotonic() < deadline:
        time.sleep(0.05)
    code, output = ctx.run([dream, "run", config, "--steps", "5"], timeout=30)
    check(code not in (1, 2) and code < 128, f"the second default run exited {code}: {tail(output)}")
    check("runs/go_to_goal_2/run.lcmlog" in output, f"the second default run did not go to runs/go_to_goal_2: "
                                                     f"{tail(output)}")
    ctx.wait("first", 60)
    check(os.path.isfile("runs/go_to_goal/run.lcmlog"), "the first default run wrote no log")

    # --- SIGKILL of launch and of sweep: the children go too ---
    killed = ctx.start("killed_launch", [dream, "launch", config, "--out", ctx.path("killed"),
                                         "--mode", "realtime", "--steps", "3000"])
    children = wait_for_children(killed.pid, 9, 10)
    # Killed once the simulator records (its signal handlers are in place by then).
    deadline = time.monotonic() + 20
    while not os.path.exists(ctx.path("killed", "run.lcmlog.part")) and time.monotonic() < deadline:
        time.sleep(0.05)
    check(os.path.exists(ctx.path("killed", "run.lcmlog.part")), "the launch's simulator never started recording")
    os.kill(killed.pid, signal.SIGKILL)
    killed.wait()
    expect_none_left(children, "dream launch")
    # The simulator got SIGTERM, as from Ctrl-C: its log and summary are whole.
    summary = read_summary(ctx.path("killed"))
    check(summary.get("end") == "interrupted", f"the killed launch's summary ends {summary.get('end')!r}")

    sweep = ctx.start("killed_sweep", [dream, "sweep", config, "--seeds", "1-4", "--jobs", "2",
                                       "--set", "world.mode=realtime", "--steps", "3000",
                                       "--out", ctx.path("sweep")])
    children = wait_for_children(sweep.pid, 2, 10)
    os.kill(sweep.pid, signal.SIGKILL)
    sweep.wait()
    expect_none_left(children, "dream sweep")

    # --- too few file descriptors, said at once ---
    started = time.monotonic()
    result = subprocess.run(["bash", "-c", 'ulimit -n 8 && exec "$@"', "bash", dream, "launch", config,
                             "--out", ctx.path("fds"), "--steps", "20"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=30)
    check(result.returncode == 1, f"launch under ulimit -n 8 exited {result.returncode}: {tail(result.stdout)}")
    check(time.monotonic() - started < 5, f"launch under ulimit -n 8 took {time.monotonic() - started:.1f} s")
    check("too few file descriptors: limit 8, need about 24 per process; raise with ulimit -n 24" in result.stdout,
          f"launch under ulimit -n 8 said: {tail(result.stdout)}")


if __name__ == "__main__":
    main(test)
