#!/usr/bin/python3
"""sim_only_hundred_robots: a run declared `sim_only: true` may have 100 robots (the Robotarium
simulator stops at 50; the bus carries 128), and everything on its way works; it never goes to
the lab.

The test writes its own config: go_to_goal, 100 robots on a 10 x 10 grid (columns 0.3 m apart,
rows 0.2 m apart, centred, all facing +x), each robot's goal 0.1 m ahead of it, so nobody
collides; the start poses are listed, as random placement cannot fit 100 robots 0.25 m apart.

1. Without `sim_only` the config is refused (exit 1) naming the file, line, `robots`, 100 and
   the way out (`add `sim_only: true``), and nothing is run.
2. `dream run` (one process, memq, lockstep) of it with `sim_only: true` finishes clean: exit 0,
   summary.json with 100 robots, `sim_only` true, no robot lost, every robot done; the report
   says "sim-only run: 100 robots, beyond the Robotarium's 50" once.
3. The same law in Python (kind python, config/python/go_to_goal.py, the embedded Python host)
   gives the same DREAM_POSES, message by message.
4. `dream render` draws the run (a PNG); `dream view RUN` serves its replay with 100 robots and
   their 100 goals.
5. `dream export` refuses it (exit 1): "<config>:<line>: sim_only: true — this run was declared
   simulation-only; remove `sim_only` ...", and writes nothing.
6. With --launch (under netns.sh: udpm in a private namespace): `dream launch` of the C++ config
   (the simulator plus 100 agent processes, about 3 s on 2 cores) finishes clean with the same
   DREAM_POSES as `dream run`, and no agent refused a message.

Usage: [netns.sh] sim_only_hundred_robots.py --dream BIN --source DIR [--launch]
"""

import json
import os
import re
import shutil
import struct
import time
import urllib.request

from dreamtest import argument_parser, check, main, read_summary, require_private_netns

ROBOTS = 100
SIM_ONLY_LINE = 4  # the line of `sim_only: true` in the config below


def grid_config(name, controller):
    """The config text: 100 robots on a grid, each driving 0.1 m ahead to its goal."""
    lines = [f"name: {name}", "seed: 1", f"robots: {ROBOTS}", "sim_only: true", "steps: 300",
             "stop_when_done: true", "initial_poses:"]
    goals = []
    for i in range(ROBOTS):
        x, y = -1.35 + 0.3 * (i % 10), -0.9 + 0.2 * (i // 10)
        lines.append(f"  - [{x:.3f}, {y:.3f}, 0.0]")
        goals.append(f"    - [{x + 0.1:.3f}, {y:.3f}]")
    lines += ["controller:"] + [f"  {line}" for line in controller] + ["  max_speed_mps: 0.15", "  goals:"] + goals
    return "\n".join(lines) + "\n"


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def check_clean_run(ctx, run, output, what):
    summary = read_summary(run)
    check(summary["robots"] == ROBOTS, f"{what}: summary.json robots {summary['robots']}, expected {ROBOTS}")
    check(summary["sim_only"] is True, f"{what}: summary.json sim_only is {summary.get('sim_only')!r}")
    check(summary["end"] == "finished", f"{what}: ended {summary['end']!r} ({summary['reason']})")
    check(summary["verdict"] == "clean", f"{what}: verdict {summary['verdict']!r}: {summary['verdict_reasons']}")
    check(summary["robots_ever_lost"] == [], f"{what}: robots lost {summary['robots_ever_lost']}")
    check(len(summary["robots_done"]) == ROBOTS, f"{what}: {len(summary['robots_done'])} robots done")
    notices = output.count("sim-only run: 100 robots, beyond the Robotarium's 50")
    check(notices == 1, f"{what}: the report says 'sim-only run' {notices} times, expected once:\n{output}")
    return summary


def check_view_replay(ctx, dream, run):
    """dream view RUN serves the replay of the 100 robots and their goals."""
    ctx.start("view", [dream, "view", run, "--port", "0"])
    output = ctx.path("view.out")
    url = None
    deadline = time.monotonic() + 15
    while url is None and time.monotonic() < deadline:
        time.sleep(0.1)
        with open(output) as f:
            found = re.search(r"open (http://127\.0\.0\.1:\d+/)", f.read())
        url = found.group(1) if found else None
    check(url is not None, "dream view printed no address within 15 s")
    no_proxy = urllib.request.build_opener(urllib.request.ProxyHandler({}))  # loopback only
    with no_proxy.open(url + "run.json", timeout=10) as response:
        replay = json.load(response)
    ctx.stop("view")
    check(replay.get("num_robots") == ROBOTS, f"dream view's replay has {replay.get('num_robots')} robots")
    check(len(replay.get("goals", [])) == ROBOTS, f"dream view's replay has {len(replay.get('goals', []))} goals")


def test(ctx):
    parser = argument_parser()
    parser.add_argument("--launch", action="store_true", help="also dream launch (needs netns.sh)")
    args = parser.parse_args()
    if args.launch:
        require_private_netns()
    dream = args.dream
    cpp = grid_config("grid100", ["kind: go_to_goal"])
    config = write(ctx.path("grid100.yaml"), cpp)

    # 1. Beyond 50 robots only with sim_only.
    plain = write(ctx.path("plain.yaml"), cpp.replace("sim_only: true\n", ""))
    code, text = ctx.run([dream, "run", plain, "--out", ctx.path("plain_run")], timeout=30)
    check(code == 1, f"dream run of 100 robots without sim_only exited {code}, expected 1")
    check(f"{plain}:3: robots: must be at most 50" in text and "got 100" in text
          and "add `sim_only: true` to run up to 128 robots in simulation only" in text,
          f"the refusal does not name file:line, robots, 100 and the way out: {text.strip()}")
    check(not os.path.exists(ctx.path("plain_run")), "a refused config left a run folder")

    # 2. One process, memq, lockstep.
    run = ctx.path("run")
    code, text = ctx.run([dream, "run", config, "--out", run], timeout=60)
    check(code == 0, f"dream run exited {code}, expected 0:\n{text}")
    summary = check_clean_run(ctx, run, text, "dream run")

    # 3. The embedded Python host drives the same 100 robots the same way.
    shutil.copy(os.path.join(args.source, "config", "python", "go_to_goal.py"), ctx.path("go_to_goal.py"))
    python = write(ctx.path("grid100_python.yaml"),
                   grid_config("grid100_python", ["kind: python", "module: go_to_goal.py", "class: GoToGoal"]))
    python_run = ctx.path("python_run")
    code, text = ctx.run([dream, "run", python, "--out", python_run], timeout=60)
    check(code == 0, f"dream run of the Python controller exited {code}, expected 0:\n{text}")
    check_clean_run(ctx, python_run, text, "dream run (Python)")
    code, text = ctx.run([dream, "log", "diff", os.path.join(run, "run.lcmlog"),
                          os.path.join(python_run, "run.lcmlog"), "--channels", "DREAM_POSES"])
    check(code == 0 and "same" in text, f"the Python run's poses differ from the C++ run's: {text.strip()}")

    # 4. Pictures and the view's replay.
    picture = ctx.path("grid100.png")
    ctx.run([dream, "render", run, "--out", picture], timeout=60, expect=0)
    with open(picture, "rb") as f:
        head = f.read(24)
    check(head[:8] == b"\x89PNG\r\n\x1a\n" and struct.unpack(">I", head[16:20])[0] == 1280,
          f"dream render wrote no 1280 px PNG at {picture}")
    check_view_replay(ctx, dream, run)

    # 5. Never to the lab.
    exported = ctx.path("export")
    code, text = ctx.run([dream, "export", run, "--out", exported], timeout=30)
    check(code == 1, f"dream export of a sim_only run exited {code}, expected 1")
    expected = (f"{run}/config.yaml:{SIM_ONLY_LINE}: sim_only: true — this run was declared simulation-only; "
                "remove `sim_only` (and use at most 20 robots) to export it")
    check(expected in text, f"dream export's refusal is not {expected!r}: {text.strip()}")
    check(not os.path.exists(exported), "a refused export left a folder")

    # 6. One process per robot.
    if args.launch:
        launched = ctx.path("launch")
        code, text = ctx.run([dream, "launch", config, "--out", launched], timeout=90)
        check(code == 0, f"dream launch exited {code}, expected 0")
        launch_summary = check_clean_run(ctx, launched, text, "dream launch")
        check(launch_summary["agents"]["bad_messages"] == {},
              f"dream launch: agents refused {launch_summary['agents']['bad_messages']}")
        check(launch_summary["steps"] == summary["steps"],
              f"steps differ: launch {launch_summary['steps']}, run {summary['steps']}")
        code, text = ctx.run([dream, "log", "diff", os.path.join(launched, "run.lcmlog"),
                              os.path.join(run, "run.lcmlog"), "--channels", "DREAM_POSES"])
        check(code == 0 and "same" in text, f"dream launch's poses differ from dream run's: {text.strip()}")
    print(f"100 robots, sim_only: {summary['steps']} steps clean in dream run (C++ and Python)"
          f"{' and dream launch' if args.launch else ''}; export refused")


if __name__ == "__main__":
    main(test)
