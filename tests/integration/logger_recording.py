#!/usr/bin/python3
"""logger_recording: a live run recorded by lcm-logger is read as the run's own log (issue 37 item 8).

In a private network namespace, lcm-logger records the bus while `dream launch` runs go_to_goal
(lockstep, paced to real time so the logger keeps up; its recording holds the world's resends of
a step and the agents' answers to them). Then:
1. python/dream_log.load reads the recording (before: "DREAM_POSES step 0 follows step 0") with
   the same steps and poses as the run's own log, its resends counted apart;
2. `dream log diff` calls the recording and the run's log the same on the world's channels
   (a resend is one message), and `--raw` still shows the datagrams that differ;
3. `dream render` of the recording draws the run's steps (not one more).
A second recording, with a `dream sim` waiting for agents on the bus beside the run, is read as
the run too: the other world's poses and status are left out and named.

Usage: netns.sh logger_recording.py --dream BIN --source DIR --types-dir DIR
"""

import os
import re
import sys

from dreamtest import arguments, check, main, require_private_netns, start_lcm_logger, stop_lcm_logger

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import dream_log  # noqa: E402


def start_logger(ctx, name):
    captured = ctx.path(name + ".lcmlog")
    start_lcm_logger(ctx, name, captured)
    return captured


def launch(ctx, args, name, steps):
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    run = ctx.path(name)
    ctx.start(name + "_launch", [args.dream, "launch", config, "--out", run, "--steps", str(steps), "--pace", "1"])
    return run, config


def test(ctx):
    args = arguments(types_dir=True)
    require_private_netns()

    # 1-3: the run alone on the bus.
    captured = start_logger(ctx, "logger")
    run, _ = launch(ctx, args, "alone", 45)
    code = ctx.wait("alone_launch", timeout=120)
    check(code == 0, f"dream launch exited {code}: {ctx.output('alone_launch')[-600:]}")
    stop_lcm_logger(ctx, "logger", captured)

    own = dream_log.load(run, args.types_dir)
    recorded = dream_log.load(captured, args.types_dir)
    check(list(recorded.steps) == list(own.steps), f"steps: recording {list(recorded.steps)[:5]}... "
          f"({len(recorded.steps)}), run log {len(own.steps)}")
    check((recorded.poses == own.poses).all(), "the recording's poses differ from the run log's")
    check(recorded.run_id == own.run_id and recorded.other_run_ids == [], f"run ids {recorded.run_id} {own.run_id}")
    # The world's channels. (The recording also holds the agents' answers to the last step, which the
    # world never took, and the run's log DREAM_APPLIED, which the world records and never sends.)
    channels = "DREAM_POSES|DREAM_STATUS|DREAM_OBSTACLES"
    code, text = ctx.run([args.dream, "log", "diff", os.path.join(run, "run.lcmlog"), captured, "--channels", channels])
    check(code == 0 and "same" in text, f"dream log diff of the recording and the run log: {text[-600:]}")
    resent = recorded.channels["DREAM_POSES"] - len(recorded.steps)
    code, text = ctx.run([args.dream, "log", "diff", os.path.join(run, "run.lcmlog"), captured, "--channels",
                          "DREAM_POSES", "--raw"])
    check((code == 1) == (resent > 0), f"--raw with {resent} resends recorded: exit {code}: {text[-300:]}")
    picture = ctx.path("recorded.png")
    code, text = ctx.run([args.dream, "render", captured, "--out", picture], timeout=60)
    check(code == 0 and os.path.isfile(picture), f"dream render of the recording: {text[-400:]}")
    code, own_text = ctx.run([args.dream, "render", run, "--out", ctx.path("own.png")], timeout=60, expect=0)
    counted = re.search(r"\(\d+ robots, \d+ steps", own_text)
    check(counted is not None and counted.group(0) in text,
          f"dream render counts the recording's steps as the run's ({own_text.strip()[-200:]}): {text[-300:]}")

    # A second world on the bus: a dream sim waiting for agents that never come.
    captured = start_logger(ctx, "logger2")
    run, config = launch(ctx, args, "beside", 90)
    ctx.wait_for_output("beside_launch", r"running \(lockstep", timeout=60)
    ctx.start("idle_sim", [args.dream, "sim", config, "--out", ctx.path("idle"), "--set",
                           "world.start_timeout_s=600"])
    ctx.wait_for_output("idle_sim", r"waiting|agents", timeout=30)
    code = ctx.wait("beside_launch", timeout=120)
    check(code in (0, 5), f"dream launch beside a second world exited {code}: {ctx.output('beside_launch')[-600:]}")
    stop_lcm_logger(ctx, "logger2", captured)
    ctx.stop("idle_sim")
    own = dream_log.load(run, args.types_dir)
    recorded = dream_log.load(captured, args.types_dir)
    check(list(recorded.steps) == list(own.steps) and (recorded.poses == own.poses).all(),
          f"beside a second world, the recording is not the run: {len(recorded.steps)} steps against "
          f"{len(own.steps)}")
    check(len(recorded.other_run_ids) == 1, f"the idle world should be named: {recorded.other_run_ids}")
    code, text = ctx.run([args.dream, "render", captured, "--out", ctx.path("beside.png")], timeout=60)
    check(code == 0, f"dream render of a recording with two worlds: {text[-400:]}")
    print(f"recordings read as their runs: {len(own.steps)} steps, {recorded.resends} resends left out, "
          f"1 other world named")


if __name__ == "__main__":
    main(test)
