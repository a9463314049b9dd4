#!/usr/bin/python3
"""Checks that the pure-Python types lcm-gen writes (build/python/dream) decode a run log.

Either give a log (--log LOG) or let the script make one (--dream BIN --config CFG: runs
`dream run CFG` into a temporary folder). Reads the log with dream_log.read_events (no LCM
runtime), decodes every DREAM_* event with its dream type, re-encodes it byte for byte,
and checks the run: DREAM_POSES steps 0..N consecutive with utime = step * 33000, the
expected number of robots, every robot inside the arena, and the final DREAM_STATUS state.

Exit 0 when every check passes; otherwise one line "FAIL: reason" and exit 1.
"""

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from dream_log import LogFormatError, read_events  # noqa: E402

MICROS_PER_STEP = 33000
ARENA_X_M = 1.6  # the Robotarium arena is x in [-1.6, 1.6] m, y in [-1, 1] m
ARENA_Y_M = 1.0


class CheckFailed(Exception):
    pass


def check(condition, message):
    if not condition:
        raise CheckFailed(message)


def types_for(dream):
    """Channel regex -> generated Python type, per the channel contract."""
    return [
        (re.compile(r"DREAM_POSES"), dream.robot_poses_t),
        (re.compile(r"DREAM_OBSTACLES"), dream.obstacles_t),
        (re.compile(r"DREAM_STATUS"), dream.run_status_t),
        (re.compile(r"DREAM_CMD_[0-9]+"), dream.velocity_command_t),
        (re.compile(r"DREAM_APPLIED"), dream.applied_commands_t),
        (re.compile(r"DREAM_VERDICT"), dream.run_verdict_t),
        (re.compile(r"DREAM_BUSY_[0-9]+"), dream.robot_busy_t),
        # DREAM_CMDS (robot_commands_t) is never in a run's log: the world records
        # each entry it takes as DREAM_CMD_<id>, so one there is an unexpected channel.
    ]


def check_log(log_path, dream, num_robots, final_state):
    """Decodes and checks the whole log; returns a dict of counts for the report."""
    table = types_for(dream)
    counts = {}
    poses_steps = []
    statuses = []
    verdicts = []
    events = 0
    try:
        for event in read_events(log_path):
            events += 1
            counts[event.channel] = counts.get(event.channel, 0) + 1
            message_type = next((t for regex, t in table if regex.fullmatch(event.channel)), None)
            if message_type is None:
                check(not event.channel.startswith("DREAM_"),
                      f"{log_path}: event {events - 1} on unexpected channel {event.channel}")
                continue
            try:
                message = message_type.decode(event.data)
            except Exception as error:  # struct.error, ValueError("Decode error"), ...
                raise CheckFailed(f"{log_path}: event {events - 1} on {event.channel} does not decode as "
                                  f"{message_type.__name__}: {error!r}") from None
            check(message.encode() == event.data,
                  f"{log_path}: event {events - 1} on {event.channel}: {message_type.__name__} re-encodes "
                  f"to different bytes (trailing bytes or wrong type)")
            if event.channel == "DREAM_POSES":
                check_poses(message, event, num_robots)
                poses_steps.append(message.step)
            elif event.channel == "DREAM_STATUS":
                check(message.num_robots == num_robots,
                      f"DREAM_STATUS step {message.step}: num_robots {message.num_robots}, expected {num_robots}")
                statuses.append(message)
            elif event.channel == "DREAM_VERDICT":
                verdicts.append((events - 1, message))
    except LogFormatError as error:
        raise CheckFailed(f"python reader: {error}") from None

    check(poses_steps, f"{log_path}: no DREAM_POSES event")
    if poses_steps != list(range(len(poses_steps))):
        index = next(i for i, step in enumerate(poses_steps) if step != i)
        raise CheckFailed(f"DREAM_POSES steps are not 0, 1, 2, ... consecutive: event {index} of the channel "
                          f"has step {poses_steps[index]}")
    check(statuses, f"{log_path}: no DREAM_STATUS event")
    last = statuses[-1]
    state_names = {dream.run_status_t.WAITING_FOR_AGENTS: "WAITING_FOR_AGENTS",
                   dream.run_status_t.RUNNING: "RUNNING", dream.run_status_t.FINISHED: "FINISHED",
                   dream.run_status_t.ABORTED: "ABORTED"}
    if final_state != "any":
        want = getattr(dream.run_status_t, final_state)
        check(last.state == want, f"final DREAM_STATUS state is {state_names.get(last.state, last.state)} "
                                  f"({last.detail!r}), expected {final_state}")
    check(last.step == poses_steps[-1],
          f"final DREAM_STATUS is at step {last.step}, the last DREAM_POSES at step {poses_steps[-1]}")
    # Issue 33: the one judge's verdict, once, the log's last event, of the run's id.
    check(len(verdicts) == 1 and verdicts[0][0] == events - 1,
          f"{log_path}: expected one DREAM_VERDICT as the last event, got {[at for at, _ in verdicts]} of {events}")
    check(verdicts[0][1].run_id == last.run_id and verdicts[0][1].step == last.step,
          f"DREAM_VERDICT of run {verdicts[0][1].run_id} step {verdicts[0][1].step}, "
          f"the last DREAM_STATUS of run {last.run_id} step {last.step}")
    return {"events": events, "steps": poses_steps[-1], "channels": counts, "final_status": last}


def check_poses(poses, event, num_robots):
    where = f"DREAM_POSES step {poses.step}"
    check(poses.num_robots == num_robots, f"{where}: num_robots {poses.num_robots}, expected {num_robots}")
    check(len(poses.x) == len(poses.y) == len(poses.theta) == num_robots,
          f"{where}: array lengths {len(poses.x)}, {len(poses.y)}, {len(poses.theta)}, expected {num_robots}")
    check(poses.utime == poses.step * MICROS_PER_STEP,
          f"{where}: utime {poses.utime}, expected step * {MICROS_PER_STEP}")
    check(event.utime == poses.utime, f"{where}: log timestamp {event.utime} != message utime {poses.utime}")
    for i, (x, y, theta) in enumerate(zip(poses.x, poses.y, poses.theta)):
        check(math.isfinite(x) and math.isfinite(y) and math.isfinite(theta),
              f"{where}: robot {i} has a non-finite pose ({x}, {y}, {theta})")
        check(abs(x) <= ARENA_X_M and abs(y) <= ARENA_Y_M,
              f"{where}: robot {i} at ({x:.3f}, {y:.3f}) is outside the arena")
        check(-math.pi - 1e-9 <= theta <= math.pi + 1e-9, f"{where}: robot {i} theta {theta} not in [-pi, pi]")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--types-dir", required=True, help="folder holding the generated package dream/")
    parser.add_argument("--log", help="run log to check")
    parser.add_argument("--summary", help="summary.json of that run (checks steps and log_events)")
    parser.add_argument("--dream", help="dream binary: make a log with `dream run --config`")
    parser.add_argument("--config", help="config for --dream")
    parser.add_argument("--robots", type=int, default=8, help="expected number of robots")
    parser.add_argument("--final-state", default="FINISHED",
                        choices=["FINISHED", "ABORTED", "RUNNING", "WAITING_FOR_AGENTS", "any"])
    args = parser.parse_args()

    sys.path.insert(0, os.path.abspath(args.types_dir))
    try:
        import dream
    except ImportError as error:
        print(f"FAIL: cannot import the generated Python types from {args.types_dir}: {error}")
        return 1

    temp = None
    try:
        log, summary = args.log, args.summary
        if log is None:
            if not (args.dream and args.config):
                parser.error("give --log, or --dream and --config")
            temp = tempfile.mkdtemp(prefix="dream_pytypes_")
            out = os.path.join(temp, "run")
            result = subprocess.run([args.dream, "-q", "run", args.config, "--out", out],
                                    stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=60)
            check(result.returncode == 0,
                  f"dream run {args.config} exited {result.returncode}: {result.stdout.strip()[-300:]}")
            log, summary = os.path.join(out, "run.lcmlog"), os.path.join(out, "summary.json")
        report = check_log(log, dream, args.robots, args.final_state)
        if summary:
            with open(summary) as f:
                data = json.load(f)
            check(data["steps"] == report["steps"],
                  f"summary.json says {data['steps']} steps, the log's last DREAM_POSES is step {report['steps']}")
            check(data["log_events"] == report["events"],
                  f"summary.json says {data['log_events']} log events, the python reader read {report['events']}")
    except CheckFailed as error:
        print(f"FAIL: {error}")
        return 1
    finally:
        if temp:
            shutil.rmtree(temp, ignore_errors=True)
    channels = ", ".join(f"{c} {n}" for c, n in sorted(report["channels"].items()))
    print(f"ok: {report['events']} events, steps 0..{report['steps']}, final state "
          f"{report['final_status'].state} ({report['final_status'].detail}); {channels}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
