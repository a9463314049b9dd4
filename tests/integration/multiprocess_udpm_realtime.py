#!/usr/bin/python3
"""multiprocess_udpm_realtime: a real-time run with one process per robot starts and finishes.

In a private network namespace, `dream launch --mode realtime --steps 45` (simulator plus 8 agent
processes over udpm; start_timeout_s lowered to 5 s) must exit 0 with end "finished" after 45
steps, no robot lost, and a log whose DREAM_POSES steps are 0..45 (read with the Python reader).
The agent processes start after the simulator has published step 0, so the world must keep
offering step 0 until they answer, in real time as in lockstep.

Usage: netns.sh multiprocess_udpm_realtime.py --dream BIN --source DIR --types-dir DIR
"""

import os

from dreamtest import (
    arguments, check, config_with, import_types, main, read_events, read_summary, require_private_netns,
)

STEPS = 45


def test(ctx):
    args = arguments(types_dir=True)
    require_private_netns()
    dream = import_types(args.types_dir)
    config = config_with(os.path.join(args.source, "config", "go_to_goal.yaml"), ctx.path("realtime.yaml"),
                         stop_when_done=False, start_timeout_s=5)
    out = ctx.path("launch")
    ctx.start("launch", [args.dream, "launch", config, "--mode", "realtime", "--steps", str(STEPS), "--out", out])
    code = ctx.wait("launch", timeout=30)
    summary = read_summary(out)
    check(code == 0, f"dream launch --mode realtime exited {code}: {summary['end']}: {summary['reason']}")
    check(summary["end"] == "finished" and summary["steps"] == STEPS,
          f"summary end {summary['end']!r} after {summary['steps']} steps, expected finished after {STEPS}")
    check(summary["mode"] == "realtime", f"summary mode {summary['mode']!r}, expected realtime")
    check(summary["robots_ever_lost"] == [], f"robots lost in real time: {summary['robots_ever_lost']}")
    steps = [dream.robot_poses_t.decode(e.data).step for e in read_events(os.path.join(out, "run.lcmlog"))
             if e.channel == "DREAM_POSES"]
    check(steps == list(range(STEPS + 1)), f"DREAM_POSES steps are not 0..{STEPS}: {steps[:5]}...{steps[-3:]}")
    # Never faster than the lab: the first step is taken at once, each further one 0.033 s later.
    least_s = (STEPS - 1) * 0.033
    check(summary["wall_time_s"] >= least_s,
          f"{STEPS} real-time steps took {summary['wall_time_s']:.3f} s wall, less than {least_s:.3f} s")
    print(f"real-time launch finished {STEPS} steps in {summary['wall_time_s']:.2f} s wall")


if __name__ == "__main__":
    main(test)
