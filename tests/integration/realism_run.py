#!/usr/bin/python3
"""realism_run: `dream run` with world.realism (issue 12 item 1).

1. `--set world.realism=lab` runs go_to_goal to its end; summary.json records the lab models; the
   log holds, for every step, DREAM_MEASURED_POSES (what the agents were sent) and DREAM_POSES (the
   truth): the truth starts exactly at the configured poses, the measurement near them but not on
   them, and summary.json's final_poses are the last true poses.
2. The same command again gives the same poses (truth and measured): lockstep is deterministic;
   --seed 2 gives other measurements.
3. Without realism (and with `realism: ideal`) the log has no DREAM_MEASURED_POSES and summary.json
   no "realism"; both give the same poses.
4. A Python controller (go_to_goal_python) with the lab preset finishes and its agents were sent
   measured poses too.
5. A bad value given with --set names the key and its range, exits 1 and makes no folder.
6. The tracker's drop, set with --set: every robot without a pose for over tracker_drop_s is lost
   to the tracker for the rest of the run, listed in summary.json realism_stats and named in a
   tracker_lost warning; its agents kept being sent its last measured pose.
7. A realism file (what dream calibrate writes): `--set world.realism.file=PATH` (absolute, and
   relative to the current folder: run from the folder holding FILE) and a config naming one
   relative to itself; summary.json names the file and has its values, the run folder keeps a copy
   (beside config.yaml, or under realism/ with config.yaml naming it) so the kept config runs again
   from anywhere, and a missing file is named with exit 1. `dream sweep --set
   world.realism.file=FILE` from the folder holding FILE: every run on the file's model, each run
   folder with its copy.

Usage: realism_run.py --dream BIN --source DIR --types-dir DIR
"""

import os

from dreamtest import arguments, check, import_types, main, read_events, read_summary

EXIT_INPUT = 1


def poses_by_channel(dream_types, run_dir):
    """{channel: [(step, x, y, theta)]} for DREAM_POSES and DREAM_MEASURED_POSES, in log order."""
    found = {"DREAM_POSES": [], "DREAM_MEASURED_POSES": []}
    for event in read_events(os.path.join(run_dir, "run.lcmlog")):
        if event.channel in found:
            p = dream_types.robot_poses_t.decode(event.data)
            found[event.channel].append((p.step, tuple(p.x), tuple(p.y), tuple(p.theta)))
    return found


def run(ctx, args, out, config, *extra, expect=0):
    return ctx.run([args.dream, "run", os.path.join(args.source, "config", config), "--out", ctx.path(out),
                    *extra], timeout=120, expect=expect)


def test(ctx):
    args = arguments(types_dir=True)
    dream_types = import_types(args.types_dir)

    # 1. The lab preset: truth and measurement in the log.
    run(ctx, args, "lab", "go_to_goal.yaml", "--set", "world.realism=lab")
    summary = read_summary(ctx.path("lab"))
    realism = summary.get("realism")
    check(realism is not None, f"summary.json has no realism: {sorted(summary)}")
    check(realism["axle_length_m"] == 0.105 and realism["pose_delay_steps"] == 1
          and realism["command_latency_steps"] == 3 and realism["motor_lag_s"] == 0.136,
          f"summary.json realism is not the lab preset: {realism}")
    stats = summary["realism_stats"]
    check(len(stats["robot_traits"]) == summary["robots"] and stats["late_steps"] > 0
          and len({t["linear_gain"] for t in stats["robot_traits"]}) == summary["robots"],
          f"realism_stats lacks each robot's drawn traits or the late steps: {stats}")
    check(summary["end"] == "finished", f"the lab run ended {summary['end']}")
    lab = poses_by_channel(dream_types, ctx.path("lab"))
    truth, measured = lab["DREAM_POSES"], lab["DREAM_MEASURED_POSES"]
    check(len(truth) > 100 and [t[0] for t in truth] == [m[0] for m in measured],
          f"DREAM_POSES ({len(truth)}) and DREAM_MEASURED_POSES ({len(measured)}) do not pair step for step")
    config_start = [(1.109, 0.287), (0.459, 0.693)]  # config/go_to_goal.yaml's first two robots
    for i, (x, y) in enumerate(config_start):
        check(truth[0][1][i] == x and truth[0][2][i] == y,
              f"true step-0 pose of robot {i} is ({truth[0][1][i]}, {truth[0][2][i]}), configured ({x}, {y})")
        error = abs(measured[0][1][i] - x)
        check(0 < error < 0.005, f"measured step-0 x of robot {i} is {error} m from the truth (noise 0.001 m)")
    final = [[truth[-1][1][i], truth[-1][2][i], truth[-1][3][i]] for i in range(len(truth[-1][1]))]
    check(summary["final_poses"] == final, "summary.json final_poses are not the last true poses")
    moved = sum(1 for a, b in zip(truth, measured) if a[1] != b[1])
    check(moved == len(truth), f"{len(truth) - moved} steps have measured x equal to the truth")

    # 2. Determinism, and the seed drives the noise.
    run(ctx, args, "lab_again", "go_to_goal.yaml", "--set", "world.realism=lab")
    check(poses_by_channel(dream_types, ctx.path("lab_again")) == lab, "the same lab run gave other poses")
    run(ctx, args, "lab_seed2", "go_to_goal.yaml", "--set", "world.realism=lab", "--seed", "2")
    seed2 = poses_by_channel(dream_types, ctx.path("lab_seed2"))
    check(seed2["DREAM_MEASURED_POSES"][0] != measured[0], "--seed 2 gave the same measured poses")

    # 3. Off: the official world, nothing added; `ideal` is the same.
    run(ctx, args, "default", "go_to_goal.yaml", "--set", "world.realism=null")
    run(ctx, args, "ideal", "go_to_goal.yaml", "--set", "world.realism=ideal")
    default = poses_by_channel(dream_types, ctx.path("default"))
    check(not default["DREAM_MEASURED_POSES"], "a run without realism has DREAM_MEASURED_POSES")
    check("realism" not in read_summary(ctx.path("default")), "a run without realism has summary.json realism")
    check(poses_by_channel(dream_types, ctx.path("ideal")) == default, "realism: ideal changed the poses")
    check(default["DREAM_POSES"] != truth, "the lab preset did not change the trajectory")

    # 4. A Python controller gets the lab too.
    run(ctx, args, "python", "go_to_goal_python.yaml", "--set", "world.realism=lab")
    python = poses_by_channel(dream_types, ctx.path("python"))
    check(read_summary(ctx.path("python"))["end"] == "finished", "the Python lab run did not finish")
    check(len(python["DREAM_MEASURED_POSES"]) == len(python["DREAM_POSES"]) > 100,
          "the Python lab run has no measured poses for every step")

    # 5. A bad value.
    code, text = run(ctx, args, "bad", "go_to_goal.yaml", "--set", "world.realism.tracking_dropout_probability=2",
                     expect=EXIT_INPUT)
    check("tracking_dropout_probability" in text and "[0, 1]" in text, f"unclear error: {text.strip()}")
    check(not os.path.exists(ctx.path("bad")), "a refused config made its run folder")
    code, text = run(ctx, args, "bad_drop", "go_to_goal.yaml", "--set", "world.realism.tracker_drop_s=-1",
                     expect=EXIT_INPUT)
    check("tracker_drop_s" in text and ">= 0 s" in text, f"unclear error: {text.strip()}")

    # 6. The tracker drops blind robots: no pose after step 0, 0.5 s allowed (15 steps of 0.033 s).
    run(ctx, args, "blind", "go_to_goal.yaml", "--set", "world.realism.preset=lab",
        "--set", "world.realism.tracking_dropout_probability=1", "--set", "world.realism.tracker_drop_s=0.5",
        "--steps", "60", expect=None)
    summary = read_summary(ctx.path("blind"))
    check(summary["realism"].get("tracker_drop_s") == 0.5 and summary["realism"].get("tracking_dropout_mean_steps") == 4,
          f"summary.json realism lacks the tracker's models: {summary['realism']}")
    lost = summary["realism_stats"]["robots_lost_to_tracker"]
    check([entry["robot"] for entry in lost] == list(range(summary["robots"])) and
          all(entry["step"] == 16 for entry in lost), f"robots lost to the tracker: {lost}")
    reasons = [r for r in summary["verdict_reasons"] if r["rule"] == "tracker_lost"]
    check(len(reasons) == 1 and reasons[0]["verdict"] == "warning" and "(from step 16)" in reasons[0]["problem"],
          f"no tracker_lost warning: {summary['verdict_reasons']}")
    blind = poses_by_channel(dream_types, ctx.path("blind"))["DREAM_MEASURED_POSES"]
    check(all(m[1:] == blind[0][1:] for m in blind), "a robot lost to the tracker was sent another pose")

    # 7. A realism file, absolute through --set, and relative to a config.
    lab_file = ctx.path("labs/mylab.yaml")
    os.makedirs(os.path.dirname(lab_file), exist_ok=True)
    with open(lab_file, "w", encoding="utf-8") as out:
        out.write("preset: lab\nmotor_lag_s: 0.2  # fitted\ncommand_latency_steps: 5\n")
    run(ctx, args, "file_abs", "go_to_goal.yaml", "--set", f"world.realism.file={lab_file}")
    realism = read_summary(ctx.path("file_abs"))["realism"]
    check(realism["file"] == lab_file and realism["motor_lag_s"] == 0.2 and realism["command_latency_steps"] == 5
          and realism["pose_quantum_rad"] == 0.001, f"summary.json realism is not the file's: {realism}")
    with open(os.path.join(args.source, "config", "go_to_goal.yaml"), encoding="utf-8") as source:
        config_text = source.read()
    with open(ctx.path("relative.yaml"), "w", encoding="utf-8") as out:
        out.write(config_text)
    relative_config = config_text.replace("realism: {preset: ideal}", "realism: {file: labs/mylab.yaml}")
    check(relative_config != config_text, "go_to_goal.yaml no longer says realism: {preset: ideal}")
    with open(ctx.path("relative.yaml"), "w", encoding="utf-8") as out:
        out.write(relative_config)
    ctx.run([args.dream, "run", ctx.path("relative.yaml"), "--out", ctx.path("file_rel"), "--steps", "30"],
            timeout=120, expect=0)
    kept = os.path.join(ctx.path("file_rel"), "labs", "mylab.yaml")
    check(os.path.exists(kept), "the run folder keeps no copy of its relative realism file")
    ctx.run([args.dream, "run", os.path.join(ctx.path("file_rel"), "config.yaml"), "--out", ctx.path("rerun"),
             "--steps", "30"], timeout=120, expect=0)
    check(read_summary(ctx.path("rerun"))["realism"]["motor_lag_s"] == 0.2, "the kept config lost its lab model")
    # From the folder holding FILE, the config elsewhere: the path is the current folder's.
    labs = os.path.dirname(lab_file)
    ctx.run([args.dream, "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", ctx.path("file_cwd"),
             "--steps", "30", "--set", "world.realism.file=mylab.yaml"], timeout=120, expect=0, cwd=labs)
    realism = read_summary(ctx.path("file_cwd"))["realism"]
    check(realism["file"] == lab_file and realism["motor_lag_s"] == 0.2, f"not the current folder's file: {realism}")
    kept = os.path.join(ctx.path("file_cwd"), "realism", "mylab.yaml")
    check(os.path.exists(kept), "the run folder keeps no copy of a realism file given with --set")
    with open(os.path.join(ctx.path("file_cwd"), "config.yaml"), encoding="utf-8") as kept_config:
        check("realism/mylab.yaml" in kept_config.read(), "the run folder's config.yaml does not name its copy")
    os.rename(lab_file, lab_file + ".moved")  # the folder alone must do
    ctx.run([args.dream, "run", os.path.join(ctx.path("file_cwd"), "config.yaml"), "--out", ctx.path("rerun_cwd"),
             "--steps", "30"], timeout=120, expect=0)
    check(read_summary(ctx.path("rerun_cwd"))["realism"]["motor_lag_s"] == 0.2, "the run folder is not on its own")
    os.rename(lab_file + ".moved", lab_file)
    code, text = run(ctx, args, "no_file", "go_to_goal.yaml", "--set", "world.realism.file=labs/none.yaml",
                     expect=EXIT_INPUT)
    check("no realism file" in text and "none.yaml" in text, f"unclear error: {text.strip()}")

    # 8. dream sweep with a realism file, from the folder holding it.
    ctx.run([args.dream, "sweep", os.path.join(args.source, "config", "go_to_goal.yaml"), "--seeds", "1-2",
             "--steps", "30", "--set", "world.realism.file=mylab.yaml", "--out", ctx.path("sweep")],
            timeout=300, expect=0, cwd=labs)
    runs_dir = os.path.join(ctx.path("sweep"), "runs")
    runs = sorted(d for d in os.listdir(runs_dir) if os.path.isfile(os.path.join(runs_dir, d, "summary.json")))
    check(len(runs) == 2, f"the sweep made {runs}")
    for name in runs:
        folder = os.path.join(runs_dir, name)
        check(read_summary(folder)["realism"]["motor_lag_s"] == 0.2, f"{name} did not run on the file's model")
        check(os.path.exists(os.path.join(folder, "realism", "mylab.yaml")), f"{name} keeps no copy of the file")


if __name__ == "__main__":
    main(test)
