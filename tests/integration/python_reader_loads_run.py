#!/usr/bin/python3
"""python_reader_loads_run: python/dream_log.py loads a run into numpy arrays that agree with the
run's summary.json and with the log's own messages, runs the example of docs/analysis.md, and
refuses bad files with an error naming the file.

Runs `dream run config/go_to_goal.yaml --steps 150` (memq://, no network), then checks:
steps and times against the summary; the last row of poses equals the last DREAM_POSES message
and summary.json's final_poses; commands[k, i] equals robot i's DREAM_CMD_<i> for step k; the
status rows end with the summary's verdict counts; obstacles per step; channel counts; and that
a text file, a cut-short log, an empty log, a log without poses, a folder without run.lcmlog, a
missing path and a wrong types folder each raise the documented error naming the file.

Usage: python_reader_loads_run.py --dream BIN --source DIR --types-dir BUILD/python
"""

import math
import os
import re
import subprocess
import sys

from dreamtest import arguments, check, fail, import_types, main, read_events, read_summary

STEPS = 150
MICROS_PER_STEP = 33000


def expect_error(load, path, error_type, fragments, **kwargs):
    """load(path) must raise error_type with every fragment in its message."""
    try:
        load(path, **kwargs)
    except error_type as error:
        missing = [f for f in fragments if f not in str(error)]
        check(not missing, f"loading {path}: message {str(error)!r} lacks {missing}")
        return str(error)
    except Exception as error:  # noqa: BLE001 - any other error is the failure to report
        fail(f"loading {path}: raised {type(error).__name__}: {error}, expected {error_type.__name__}")
    fail(f"loading {path}: no error, expected {error_type.__name__}")


def test(ctx):
    args = arguments(types_dir=True)
    sys.path.insert(0, os.path.join(args.source, "python"))
    import numpy as np
    import dream_log

    out = ctx.path("go_to_goal")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--steps", str(STEPS),
             "--out", out], timeout=60, expect=0)
    summary = read_summary(out)
    run = dream_log.load(out, types_dir=args.types_dir)
    n = summary["robots"]
    k = summary["steps"] + 1

    # Shapes and steps.
    check(run.num_robots == n, f"num_robots {run.num_robots}, summary says {n}")
    check(run.steps.tolist() == list(range(k)), f"steps {run.steps[:3]}..{run.steps[-1]}, expected 0..{k - 1}")
    check(run.poses.shape == (k, n, 3), f"poses shape {run.poses.shape}, expected {(k, n, 3)}")
    check(run.velocities.shape == (k, n, 2), f"velocities shape {run.velocities.shape}")
    check(run.commands.shape == (k, n, 2) and run.done.shape == (k, n), f"commands shape {run.commands.shape}")
    check(np.allclose(run.t_s, run.steps * MICROS_PER_STEP * 1e-6, atol=1e-12), "t_s is not step * 0.033")
    check(len(run.obstacles) == k, f"{len(run.obstacles)} obstacle rows for {k} steps")

    # Independently decoded messages: the last DREAM_POSES and every command.
    dream = import_types(args.types_dir)
    last_poses = None
    commands = {}
    for event in read_events(run.log_path):
        if event.channel == "DREAM_POSES":
            last_poses = dream.robot_poses_t.decode(event.data)
        match = re.fullmatch(r"DREAM_CMD_([0-9]+)", event.channel)
        if match:
            command = dream.velocity_command_t.decode(event.data)
            commands.setdefault((command.step, int(match.group(1))), (command.v, command.w, command.done))
    final = np.column_stack([last_poses.x, last_poses.y, last_poses.theta])
    check(np.array_equal(run.poses[-1], final), f"poses[-1] {run.poses[-1][0]} != last DREAM_POSES {final[0]}")
    check(np.allclose(run.poses[-1], np.array(summary["final_poses"]), rtol=0, atol=1e-12),
          "poses[-1] differ from summary.json final_poses")
    check(np.array_equal(run.velocities[-1], np.column_stack([last_poses.v, last_poses.w])),
          "velocities[-1] differ from the last DREAM_POSES v, w")
    check(commands, "the log holds no DREAM_CMD_<id> message")
    for (step, robot), (v, w, done) in commands.items():
        if step >= k:
            continue
        check(tuple(run.commands[step, robot]) == (v, w) and run.done[step, robot] == done,
              f"commands[{step}, {robot}] = {run.commands[step, robot]}, done {run.done[step, robot]}; "
              f"the log says ({v}, {w}), done {done}")
    answered = ~np.isnan(run.commands[:, :, 0])
    check(int(answered.sum()) == len([key for key in commands if key[0] < k]),
          f"{int(answered.sum())} commands in the array, {len(commands)} (step, robot) pairs in the log")
    # Lockstep, nobody lost: every robot answered every step but the last (the run ended there).
    check(answered[:-1].all(), f"steps without a command: {np.argwhere(~answered[:-1])[:3].tolist()}")

    # Status: running totals that end with the summary's verdict counts.
    check(run.final_state == "FINISHED", f"final state {run.final_state} ({run.final_detail})")
    check(run.status["step"][-1] == summary["steps"], f"last status step {run.status['step'][-1]}")
    for name, value in summary["violations"].items():
        check(int(run.status[name][-1]) == value, f"status {name} ends at {run.status[name][-1]}, summary {value}")
    check(sum(run.channels.values()) == summary["log_events"],
          f"{sum(run.channels.values())} events read, summary.json says {summary['log_events']}")
    check(all(o.shape == (2, 7) for o in run.obstacles), "go_to_goal has 2 obstacles at every step")
    # The moving bar (0.1 m/s towards +x, from x = -1.3) is published where it is at each step.
    bar_x = np.array([o[1, 1] for o in run.obstacles])
    check(np.allclose(np.diff(bar_x), 0.1 * 0.033), f"obstacle 1 does not advance 3.3 mm a step: {np.diff(bar_x)[:3]}")
    check(abs(bar_x[0] + 1.3) < 1e-9, f"obstacle 1 starts at x = {bar_x[0]}, config says -1.3")
    check(run.summary == summary, "run.summary is not the folder's summary.json")
    # Each robot's path, from the arrays, against the log decoded directly.
    moved = np.linalg.norm(run.poses[-1, :, :2] - run.poses[0, :, :2], axis=1)
    check((moved > 0.01).all(), f"robots barely moved in {STEPS} steps: {moved}")

    # The example of docs/analysis.md, as written, on this run.
    with open(os.path.join(args.source, "docs", "analysis.md")) as f:
        doc = f.read()
    example = re.search(r"<!-- analysis-example -->\s*```python\n(.*?)```", doc, re.S)
    check(example, "docs/analysis.md has no ```python block after <!-- analysis-example -->")
    script = example.group(1).replace('"runs/go_to_goal"', repr(out))
    # As a reader runs it: in a checkout built in build/, dream_log finds the types by itself
    # (and must not take the runtime package python/dream/ for them); another build dir is named.
    env = dict(os.environ)
    env.pop("DREAM_PYTHON_TYPES_DIR", None)
    if os.path.realpath(args.types_dir) != os.path.realpath(os.path.join(args.source, "build", "python")):
        env["DREAM_PYTHON_TYPES_DIR"] = args.types_dir
    result = subprocess.run([sys.executable, "-c", script], cwd=args.source, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=60)
    check(result.returncode == 0, f"the docs example failed: {result.stdout[-600:]}")
    xy = run.poses[:, :, :2]
    lengths = np.linalg.norm(np.diff(xy, axis=0), axis=2).sum(axis=0)
    for robot in range(n):
        want = f"robot {robot}: {lengths[robot]:.2f} m"
        check(want in result.stdout, f"the docs example does not print {want!r}: {result.stdout[-400:]}")
    closest = min(math.dist(xy[s, i], xy[s, j]) for s in range(k) for i in range(n) for j in range(i + 1, n))
    metric = summary["metrics"]["min_pairwise_distance_m"]
    check(abs(closest - metric) < 1e-9, f"closest approach {closest} m from the arrays, {metric} m in summary.json")
    check(f"closest approach {closest:.3f} m" in result.stdout,
          f"the docs example's closest approach is not {closest:.3f} m: {result.stdout[-400:]}")

    # Bad files: each error names the file.
    text_file = ctx.path("notes.lcmlog")
    with open(text_file, "w") as f:
        f.write("these are notes, not a log\n")
    expect_error(dream_log.load, text_file, dream_log.LogFormatError, [text_file, "not an LCM log"],
                 types_dir=args.types_dir)
    with open(run.log_path, "rb") as f:
        data = f.read()
    cut = ctx.path("cut.lcmlog")
    with open(cut, "wb") as f:
        f.write(data[:len(data) // 2])
    expect_error(dream_log.load, cut, dream_log.LogFormatError, [cut, "cut short"], types_dir=args.types_dir)
    empty = ctx.path("empty.lcmlog")
    open(empty, "wb").close()
    expect_error(dream_log.load, empty, dream_log.RunLogError, [empty, "no DREAM_POSES"], types_dir=args.types_dir)
    no_poses = ctx.path("no_poses.lcmlog")
    events = list(read_events(run.log_path))
    with open(no_poses, "wb") as f:
        for index, event in enumerate(e for e in events if e.channel != "DREAM_POSES"):
            channel = event.channel.encode()
            f.write(b"".join([(0xEDA1DA01).to_bytes(4, "big"), index.to_bytes(8, "big"),
                              event.utime.to_bytes(8, "big"), len(channel).to_bytes(4, "big"),
                              len(event.data).to_bytes(4, "big"), channel, event.data]))
    expect_error(dream_log.load, no_poses, dream_log.RunLogError, [no_poses, "no DREAM_POSES"],
                 types_dir=args.types_dir)
    wrong_type = ctx.path("wrong_type.lcmlog")
    status_event = next(e for e in events if e.channel == "DREAM_STATUS")
    with open(wrong_type, "wb") as f:
        f.write(b"".join([(0xEDA1DA01).to_bytes(4, "big"), (0).to_bytes(8, "big"), (0).to_bytes(8, "big"),
                          len(b"DREAM_POSES").to_bytes(4, "big"), len(status_event.data).to_bytes(4, "big"),
                          b"DREAM_POSES", status_event.data]))
    expect_error(dream_log.load, wrong_type, dream_log.RunLogError, [wrong_type, "event 0", "robot_poses_t"],
                 types_dir=args.types_dir)
    os.mkdir(ctx.path("empty_folder"))
    expect_error(dream_log.load, ctx.path("empty_folder"), dream_log.RunLogError,
                 [ctx.path("empty_folder"), "run.lcmlog"], types_dir=args.types_dir)
    expect_error(dream_log.load, ctx.path("no_such_run"), FileNotFoundError, [ctx.path("no_such_run")],
                 types_dir=args.types_dir)
    expect_error(dream_log.import_types, ctx.path("no_types"), ImportError, [ctx.path("no_types")])
    print(f"loaded {run}: poses {run.poses.shape}, {int(answered.sum())} commands, {len(run.status)} status rows")


if __name__ == "__main__":
    main(test)
