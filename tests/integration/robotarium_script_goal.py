#!/usr/bin/python3
"""robotarium_script_goal: the goal of a Robotarium script's run (docs/robotarium-scripts.md#the-goal).

A script declares its goal the way Robotarium scripts do, by the at_position / at_pose check that
ends its main loop; a config (or --set) may give one with controller.goal_points / goal_poses.

- A script looping until `at_position(x, goals)[0]`: summary.json's goal is judged (has_criterion),
  met, its detail names the script's last at_position check and its tolerance, its completion step
  is a step of the run, the goal points are the script's targets, and the exit code is 0.
- The same script stopped after a few steps (the check never passed): goal missed, verdict
  not_ready with the reason goal, exit 5, as any run whose goal was missed.
- A script with no check: no goal declared (has_criterion false), exit 0.
- That script with --set controller.goal_points (its robots' own start points, so met at once):
  judged by the key; with the wrong count of points it is refused before anything runs, naming
  controller.goal_points (exit 1).
- `dream sweep` of the looping script over two seeds: sweep.csv says success (goal met) for both and
  sweep.md a success rate of 2 of 2, where a script without a goal says "no goal declared".

Skipped (77) without numpy or cvxopt.
Usage: robotarium_script_goal.py --dream BIN --source DIR
"""

import csv
import os

from dreamtest import argument_parser, check, main, read_summary, script_under_test, tail

LOOPING = """
import numpy as np
import rps.robotarium as robotarium
from rps.utilities.misc import create_at_position, generate_random_positions
from rps.utilities.transformations import create_si_to_uni_dynamics

N = 2
goals = np.array([[-0.3, 0.4], [0.2, -0.2]]) + 0.1 * (np.random.rand(2, N) - 0.5)
r = robotarium.Robotarium(number_of_robots=N, show_figure=False, sim_in_real_time=False,
                          initial_conditions=np.array([[-0.6, 0.6], [0.0, 0.0], [0.0, 0.0]]))
si_to_uni = create_si_to_uni_dynamics()
at_position = create_at_position(position_error=0.04)
x = r.get_poses()
r.step()
k = 0
while not at_position(x, goals)[0] and k < LIMIT:
    x = r.get_poses()
    r.set_velocities(np.arange(N), si_to_uni(1.0 * (goals - x[:2, :]), x))
    r.step()
    k += 1
r.debug()
"""

NO_CHECK = """
import numpy as np
import rps.robotarium as robotarium

r = robotarium.Robotarium(number_of_robots=2, show_figure=False, sim_in_real_time=False,
                          initial_conditions=np.array([[-0.6, 0.6], [0.0, 0.0], [0.0, 0.0]]))
for _ in range(10):
    r.get_poses()
    r.step()
r.debug()
"""


def run(ctx, args, script, name, *extra):
    out = ctx.path(name)
    code, output = ctx.run([args.dream, "run", script, "--out", out, "-q", *extra], timeout=600)
    return out, code, output


def check_met(ctx, args, looping):
    out, code, output = run(ctx, args, looping, "met")
    check(code == 0, f"the looping script exited {code}: {tail(output, 1500)}")
    summary = read_summary(out)
    goal = summary["goal"]
    check(goal["has_criterion"] and goal["met"], f"the script's own check is not its goal, met: {goal}")
    check("the script's last at_position check" in goal["detail"] and "0.04 m" in goal["detail"],
          f"the goal's detail does not name the script's check and tolerance: {goal}")
    check(0 < goal["completion_step"] <= summary["steps"], f"completion step {goal} of {summary['steps']} steps")
    points = summary["metrics"]["goal_points"]
    check(len(points) == 2 and len(points[0]) == 1, f"the goal points are not the script's targets: {points}")
    check(summary["metrics"]["goal_final_max_error_m"] <= 0.04, f"metrics: {summary['metrics']}")


def check_missed(ctx, args, looping_text):
    short = script_under_test(ctx, "goal_short.py", looping_text.replace("LIMIT", "5"))
    out, code, output = run(ctx, args, short, "missed")
    check(code == 5, f"a script stopped short of its check's goal exited {code}, not 5: {tail(output, 1500)}")
    summary = read_summary(out)
    check(summary["goal"]["has_criterion"] and not summary["goal"]["met"], f"goal: {summary['goal']}")
    check(summary["verdict"] == "not_ready" and any(r["rule"] == "goal" for r in summary["verdict_reasons"]),
          f"verdict {summary['verdict']}, reasons {summary['verdict_reasons']}")


def check_keys(ctx, args):
    script = script_under_test(ctx, "goal_none.py", NO_CHECK)
    out, code, output = run(ctx, args, script, "none")
    check(code == 0, f"a script with no check exited {code}: {tail(output, 1500)}")
    check(not read_summary(out)["goal"]["has_criterion"], f"a script with no check declared a goal: {out}")
    out, code, output = run(ctx, args, script, "keys", "--set", "controller.goal_points=[[-0.6, 0.0], [0.6, 0.0]]")
    check(code == 0, f"goal_points at the start poses: exit {code}: {tail(output, 1500)}")
    goal = read_summary(out)["goal"]
    check(goal["has_criterion"] and goal["met"] and "controller.goal_points" in goal["detail"], f"goal: {goal}")
    out, code, output = run(ctx, args, script, "bad_keys", "--set", "controller.goal_points=[[0, 0]]")
    check(code == 1 and "controller.goal_points" in output and "per robot (2)" in output,
          f"one goal point for two robots: exit {code}: {tail(output, 1500)}")


def check_sweep(ctx, args, looping):
    out = ctx.path("sweep")
    code, output = ctx.run([args.dream, "sweep", looping, "--seeds", "1-2", "--jobs", "2", "--out", out],
                           timeout=900)
    check(code == 0, f"dream sweep exited {code}: {tail(output, 2000)}")
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    check([row["success"] for row in rows] == ["true", "true"] and all(row["goal_met"] == "true" for row in rows),
          f"sweep.csv: {rows}")
    with open(os.path.join(out, "sweep.md")) as f:
        table = f.read()
    check("| success rate | 2 of 2" in table, f"sweep.md has no success rate: {tail(table, 1500)}")


def test(ctx):
    args = argument_parser().parse_args()
    looping_text = LOOPING
    looping = script_under_test(ctx, "goal_loop.py", looping_text.replace("LIMIT", "2000"))
    check_met(ctx, args, looping)
    check_missed(ctx, args, looping_text)
    check_keys(ctx, args)
    check_sweep(ctx, args, looping)


if __name__ == "__main__":
    main(test)
