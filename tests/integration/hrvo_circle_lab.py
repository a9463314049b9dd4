#!/usr/bin/python3
"""hrvo_circle_lab: the HRVO circle swap under the lab preset (docs/experiments.md#robustness-ideal-vs-lab).

1. `dream run config/hrvo_circle.yaml --set world.realism=lab` with seeds 7, 15 and 17, those of
   the robustness tables that missed the third formation when robots drove at full speed up to
   the 5 cm tolerance: all now end with every robot done, all three formations complete on the
   true poses, verdict clean, exit 0.
2. The Python twin (config/hrvo_circle_python.yaml) under the lab preset, seed 15: the same true
   poses as the C++ run at every step.
3. `gain: 4, stop_m: 0.05` is the thesis's Robot_c: under the lab preset re-derived in issue 32
   (seeds 1-20, 2026-12-02) seed 7 misses the third formation at full speed (exit 5, "2 of 3
   formations") where the slow approach completes it, so the check in 1 can fail.

Usage: hrvo_circle_lab.py --dream BIN --source DIR --types-dir DIR
"""

import os

from dreamtest import arguments, check, import_types, main, read_events, read_summary

EXIT_NOT_READY = 5


def poses_by_step(dream_types, run_dir):
    """step -> (x, y, theta tuples) of every DREAM_POSES (true pose) event."""
    poses = {}
    for event in read_events(os.path.join(run_dir, "run.lcmlog")):
        if event.channel == "DREAM_POSES":
            message = dream_types.robot_poses_t.decode(event.data)
            poses[message.step] = (tuple(message.x), tuple(message.y), tuple(message.theta))
    return poses


def run(ctx, args, out, config, seed, *extra, expect=0):
    ctx.run([args.dream, "run", os.path.join(args.source, "config", config), "--seed", str(seed), "--set",
             "world.realism=lab", *extra, "--out", ctx.path(out), "-q"], timeout=120, expect=expect)
    return read_summary(ctx.path(out))


def test(ctx):
    args = arguments(types_dir=True)
    dream_types = import_types(args.types_dir)

    # 1. The seeds that failed at full speed (15, 17 under issue 22's preset; 7 under issue 32's) complete.
    for seed in (7, 15, 17):
        summary = run(ctx, args, f"cpp_{seed}", "hrvo_circle.yaml", seed)
        metrics = summary["metrics"]
        check(summary["reason"] == "every robot reported done" and summary["robots_done"] == list(range(10)),
              f"seed {seed}: {summary['reason']}, done {summary['robots_done']}")
        check(metrics["goal"]["met"] and metrics["formations_completed"] == 3.0,
              f"seed {seed}: goal {metrics['goal']}")
        check(summary["verdict"] == "clean" and summary["violations"]["collision_errors"] == 0,
              f"seed {seed}: verdict {summary['verdict']}, violations {summary['violations']}")

    # 2. The Python twin drives the same true poses under the lab preset.
    run(ctx, args, "python_15", "hrvo_circle_python.yaml", 15)
    check(poses_by_step(dream_types, ctx.path("python_15")) == poses_by_step(dream_types, ctx.path("cpp_15")),
          "the Python and C++ HRVO circle swaps differ under the lab preset")

    # 3. The thesis's full-speed approach fails seed 7: the check above can fail.
    # From the start poses the robustness tables were measured on (0.3 m apart, before the config's
    # start poses became lab_safe: its 0.5 m poses give other runs per seed).
    summary = run(ctx, args, "thesis_7", "hrvo_circle.yaml", 7, "--set", "controller.gain=4", "--set",
                  "controller.stop_m=0.05", "--set", "initial_poses.generate.lab_safe=false", "--set",
                  "initial_poses.generate.min_spacing_m=0.3", expect=EXIT_NOT_READY)
    check(summary["metrics"]["goal"]["detail"] == "2 of 3 formations",
          f"Robot_c's approach under lab, seed 7: {summary['metrics']['goal']}")


if __name__ == "__main__":
    main(test)
