#!/usr/bin/python3
"""startup_drive_cli: the Robotarium's start-up drive through the `dream` command (issue 33 item 1).

1. `dream run` of tests/data/startup_crowded.yaml (nine robots 0.2 m apart) runs but warns that the
   drive settled from 0 of 5 placements, naming robots and distances; with `--set
   world.start=placed` it is refused (exit 1) before any folder is made; a bad world.start names
   the key and the choices.
2. `world.start: placed` on config/go_to_goal.yaml: the drive's steps are in the log on
   DREAM_STARTUP_POSES (steps 1..K, negative utimes), the experiment still starts at step 0 where
   the drive ended (near, not on, the start poses) and counts no error of the drive.
3. `initial_poses: {generate: {lab_safe: true}}` runs; with min_spacing_m 0.19 it is refused naming
   the spacing and how many placements settled.
4. `dream sweep` of the crowded config warns at planning; `dream export` of its run warns loudly.

Usage: startup_drive_cli.py --dream BIN --source DIR --types-dir DIR
"""

import math
import os

from dreamtest import arguments, check, import_types, main, read_events, read_summary

EXIT_INPUT = 1


def crowded(args):
    return os.path.join(args.source, "tests", "data", "startup_crowded.yaml")


def run_warns_or_refuses(ctx, args):
    out = ctx.path("crowded")
    code, text = ctx.run([args.dream, "run", crowded(args), "--out", out], timeout=120)
    check(code != EXIT_INPUT and os.path.isfile(os.path.join(out, "summary.json")),
          f"dream run of the crowded config exited {code} without a run: {text[-400:]}")
    check("start-up drive settled from 0 of 5 random charger placements" in text,
          f"dream run does not warn that the start-up drive fails: {text[-600:]}")
    check("robot 4 " in text and " m / " in text, f"the warning names no robots and distances: {text[-600:]}")

    placed = ctx.path("crowded_placed")
    code, text = ctx.run([args.dream, "run", crowded(args), "--out", placed, "--set", "world.start=placed"],
                         timeout=120)
    check(code == EXIT_INPUT, f"world.start=placed on the crowded config exited {code}, expected 1: {text[-400:]}")
    check("settled from 0 of 5" in text and "cannot start" in text and "robot " in text,
          f"the refusal does not say why: {text[-600:]}")
    check(not os.path.exists(placed), "a refused run left a folder")

    code, text = ctx.run([args.dream, "run", crowded(args), "--out", ctx.path("bad"), "--set",
                          "world.start=sideways"])
    check(code == EXIT_INPUT and "sideways" in text and "placed" in text,
          f"a bad world.start is not named with its choices (exit {code}): {text[-300:]}")
    return "crowded: dream run warns, world.start=placed refuses, a bad world.start is named"


def placed_run(ctx, args, dream_types):
    out = ctx.path("placed")
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    ctx.run([args.dream, "run", config, "--out", out, "--set", "world.start=placed", "--steps", "3", "--all-steps"],
            expect=0, timeout=120)
    drive, poses = [], []
    for event in read_events(os.path.join(out, "run.lcmlog")):
        if event.channel == "DREAM_STARTUP_POSES":
            drive.append(dream_types.robot_poses_t.decode(event.data))
        elif event.channel == "DREAM_POSES":
            poses.append(dream_types.robot_poses_t.decode(event.data))
    check(len(drive) > 10, f"{len(drive)} start-up drive steps in the log")
    check([m.step for m in drive] == list(range(1, len(drive) + 1)), "the drive's steps are not 1..K")
    check(drive[-1].utime == -33000 and all(m.utime < 0 for m in drive), "the drive's utimes are not before step 0")
    check(poses[0].step == 0, f"the experiment starts at step {poses[0].step}")
    check(list(poses[0].x) == list(drive[-1].x) and list(poses[0].theta) == list(drive[-1].theta),
          "step 0 is not where the drive ended")
    with open(config) as f:
        lines = f.read().split("initial_poses:", 1)[1].splitlines()[1:9]
    starts = [[float(v) for v in line.split("[", 1)[1].split("]", 1)[0].split(",")] for line in lines]
    off = [math.hypot(poses[0].x[i] - s[0], poses[0].y[i] - s[1]) for i, s in enumerate(starts)]
    check(max(off) < 0.06 and max(off) > 0.0, f"step 0 is {max(off):.4f} m from the start poses at most")
    summary = read_summary(out)
    check(summary["steps"] == 3, f"summary.json counts {summary['steps']} steps, the experiment's are 3")
    return f"placed: {len(drive)} drive steps logged apart, step 0 within {max(off):.3f} m of the start poses"


def lab_safe(ctx, args):
    def config(name, seed, extra):
        path = ctx.path(name + ".yaml")
        with open(path, "w") as f:
            f.write(f"name: {name}\nseed: {seed}\nrobots: 10\nsteps: 3\n"
                    f"initial_poses: {{generate: {{lab_safe: true{extra}}}}}\n"
                    "controller:\n  kind: line_deployment\n")
        return path

    code, text = ctx.run([args.dream, "run", config("safe", 1, ""), "--out", ctx.path("safe")], timeout=120)
    check(code != EXIT_INPUT and os.path.isfile(os.path.join(ctx.path("safe"), "summary.json")),
          f"lab_safe: true with 10 robots was refused (exit {code}): {text[-400:]}")
    code, text = ctx.run([args.dream, "run", config("tight", 2, ", min_spacing_m: 0.19"), "--out",
                          ctx.path("tight")], timeout=120)
    check(code == EXIT_INPUT, f"lab_safe with min_spacing_m 0.19 exited {code}, expected 1: {text[-300:]}")
    check("lab_safe" in text and "0.190 m apart" in text and "settled from 0 of 5" in text,
          f"the refusal names no spacing or placements: {text[-500:]}")
    return "lab_safe: 10 robots at the official 0.5 m run, 0.19 m is refused"


def sweep_and_export(ctx, args):
    sweep = ctx.path("sweep")
    code, text = ctx.run([args.dream, "sweep", crowded(args), "--seeds", "3", "--steps", "2", "--out", sweep],
                         timeout=180)
    check("run " in text and "start-up drive settled from 0 of 5" in text,
          f"dream sweep does not warn at planning (exit {code}): {text[-500:]}")
    code, text = ctx.run([args.dream, "export", ctx.path("crowded"), "--out", ctx.path("export")], timeout=120)
    check("THE LAB WOULD LIKELY REJECT THIS RUN BEFORE STEP 0" in text and "settled from 0 of 5" in text,
          f"dream export does not warn loudly (exit {code}): {text[-500:]}")
    return "sweep warns at planning, export warns loudly"


def test(ctx):
    args = arguments(types_dir=True)
    dream_types = import_types(args.types_dir)
    for part in (lambda: run_warns_or_refuses(ctx, args), lambda: placed_run(ctx, args, dream_types),
                 lambda: lab_safe(ctx, args), lambda: sweep_and_export(ctx, args)):
        print(part())


if __name__ == "__main__":
    main(test)
