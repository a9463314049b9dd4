#!/usr/bin/python3
"""python_goal: a Python controller's own goal and metrics (its class's goal_points, metrics and
goal, docs/python-controllers.md#your-own-goal-and-metrics) reach summary.json, the verdict and
a sweep's success column; a class that declares none gets "no goal declared", never "success".

1. `dream run` of two robots driving to their points with a goal that holds (required_m 0.05):
   summary.json goal met, judged, with its completion step; the class's figures and goal
   points under metrics; verdict clean, exit 0.
2. The same with a goal the run misses (required_m 0.001): goal not met, verdict not_ready
   (exit 5) with the goal's reason.
3. `dream sweep --set controller.required_m=0.05,0.001`: the first row a success, the second not.
4. The class without a goal: the sweep says "no goal declared" (csv success false, sweep.md).
   `dream render --plot --metric worst_error_m` draws the class's series; `dream compare` lists
   its figures and goal.
5. A goal() that raises: summary.json metrics.error names the module and line; not a success.
   With --steps too (issue 34): a goal() that raises or goal_points() that are unusable make the run
   not_ready ("could not be judged"), exit 5; only a goal not reached yet is "not judged".
6. No run leaves __pycache__ beside the module.

Usage: python_goal.py --dream BIN --source DIR
"""

import csv
import json
import os
import textwrap

from dreamtest import Context, arguments, check, main, read_summary  # noqa: F401

MODULE = textwrap.dedent('''
    import math

    import numpy as np

    from dream import Robot, SingleIntegratorToUnicycle, key

    POINTS = [(-0.4, 0.0), (0.4, 0.0)]


    class Pair(Robot):
        KEYS = {"required_m": key(0.05, above=0.0)}

        def setup(self):
            self.si_to_uni = SingleIntegratorToUnicycle()
            self.arrived = False

        def update(self, step):
            if not self.has_odometry:
                return (0.0, 0.0)
            x, y, theta = self.pose.tolist()
            dx, dy = POINTS[self.id][0] - x, POINTS[self.id][1] - y
            self.arrived = math.hypot(dx, dy) <= 0.02
            if self.arrived:
                return (0.0, 0.0)
            scale = min(1.0, 0.15 / max(math.hypot(dx, dy), 1e-9))
            return self.limit_actuators(self.si_to_uni.map([dx * scale, dy * scale], theta))

        def done(self):
            return self.arrived

        @classmethod
        def goal_points(cls, config, num_robots):
            return [[point] for point in POINTS]

        @classmethod
        def metrics(cls, run):
            errors = run.distances_to(POINTS)
            return {"worst_error_m": errors.max(axis=1), "final_error_m": errors[-1]}

        @classmethod
        def goal(cls, run, metrics):
            close = metrics["worst_error_m"] < run.config["required_m"]
            return {"met": bool(close[-1]), "completion_step": run.first_step_where(close),
                    "detail": f"worst {metrics['worst_error_m'][-1]:.3f} m"}
    ''')

CONFIG = textwrap.dedent('''
    name: pair
    robots: 2
    steps: 600
    initial_poses: [[-0.9, 0.3, 0.0], [0.9, -0.3, 3.14]]
    controller:
      kind: python
      module: pair.py
      class: {cls}
      required_m: {required}
    ''')


def write_experiment(folder, module_text, cls="Pair", required=0.05):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "pair.py"), "w") as f:
        f.write(module_text)
    path = os.path.join(folder, "pair.yaml")
    with open(path, "w") as f:
        f.write(CONFIG.format(cls=cls, required=required))
    return path


def read_csv(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def single_runs(context, dream):
    config = write_experiment(context.path("met"), MODULE)
    code, output = context.run([dream, "run", config, "--out", context.path("met", "run")], timeout=120)
    check(code == 0, f"dream run with a goal that holds: exit {code}: {output[-400:]}")
    summary = read_summary(context.path("met", "run"))
    goal = summary["goal"]
    check(goal["has_criterion"] and goal["met"] and goal["judged"] and goal["completion_step"] > 0,
          f"summary.json goal: {goal}")
    check(summary["verdict"] == "clean", f"verdict {summary['verdict']}")
    metrics = summary["metrics"]
    check(metrics["goal_points"] == [[[-0.4, 0.0]], [[0.4, 0.0]]], f"goal points: {metrics.get('goal_points')}")
    check(len(metrics["final_error_m"]) == 2 and max(metrics["final_error_m"]) <= 0.02,
          f"final_error_m: {metrics.get('final_error_m')}")
    check(metrics["worst_error_m"][-1][0] == summary["steps"] - 1 or metrics["worst_error_m"][-1][0] == summary["steps"],
          f"worst_error_m should be a series ending at the last step: {metrics['worst_error_m'][-1]}")

    # The module's folder holds only what the user put there: no __pycache__ from the agents'
    # interpreter or the metrics' python3 (PYTHONDONTWRITEBYTECODE is unset for this test).
    cached = [root for root, dirs, _ in os.walk(context.path("met")) if "__pycache__" in dirs]
    check(not cached, f"dream run left __pycache__ in {cached}")

    plot = context.path("met", "plot.png")
    code, output = context.run([dream, "render", context.path("met", "run"), "--plot", "--metric", "worst_error_m",
                                "--out", plot], timeout=60)
    check(code == 0 and "(1 series)" in output and os.path.isfile(plot), f"--plot of the class's series: {output[-300:]}")

    config = write_experiment(context.path("missed"), MODULE, required=0.001)
    code, output = context.run([dream, "run", config, "--out", context.path("missed", "run")], timeout=120)
    summary = read_summary(context.path("missed", "run"))
    check(code == 5 and not summary["goal"]["met"] and summary["goal"]["has_criterion"],
          f"a missed goal: exit {code}, goal {summary['goal']}: {output[-400:]}")
    check(summary["verdict"] == "not_ready" and any(r["rule"] == "goal" for r in summary["verdict_reasons"]),
          f"verdict {summary['verdict']}, reasons {summary['verdict_reasons']}")

    # dream compare: the class's figures and goal of both runs, side by side.
    code, output = context.run([dream, "compare", context.path("met", "run"), context.path("missed", "run"),
                                "--out", context.path("compared")], timeout=60)
    check(code == 0 and "worst_error_m:" in output and "final_error_m:" in output and '"met":true' in output,
          f"dream compare: exit {code}: {output[-600:]}")
    # Two simulated runs are named so, not "(lab)" (issue 37): what each is comes from its summary.json.
    check("first (simulation): " in output and "second (simulation): " in output and "(lab)" not in output,
          f"dream compare names two simulated runs: {output[:400]}")
    with open(context.path("compared", "comparison.json")) as f:
        compared = json.load(f)
    check(compared["first"]["what"] == "simulation" and compared["second"]["what"] == "simulation",
          f"comparison.json's what: {compared['first'].get('what')}, {compared['second'].get('what')}")


def sweeps(context, dream):
    config = write_experiment(context.path("sweep"), MODULE)
    out = context.path("sweep", "out")
    code, output = context.run([dream, "-q", "sweep", config, "--set", "controller.required_m=0.05,0.001",
                                "--out", out], timeout=240)
    check(code in (0, 5), f"sweep exit {code}: {output[-400:]}")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check([r["success"] for r in rows] == ["true", "false"], f"success column: {[(r['run'], r['success']) for r in rows]}")

    bare = MODULE.split("    @classmethod")[0]
    check("def goal" not in bare and "def done" in bare, "internal: the class without its declarations")
    config = write_experiment(context.path("bare"), bare)
    out = context.path("bare", "out")
    code, output = context.run([dream, "sweep", config, "--seeds", "1-2", "--out", out], timeout=240)
    check(code == 0, f"sweep without a goal: exit {code}: {output[-400:]}")
    check("no goal declared" in output and ": success" not in output, f"progress lines: {output[-600:]}")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check([r["success"] for r in rows] == ["false", "false"] and all(r["goal"] == "no goal declared" for r in rows),
          f"rows without a goal: {rows}")
    with open(os.path.join(out, "sweep.md")) as f:
        md = f.read()
    check("| success rate | no goal declared" in md and "| success |" not in md.split("## Runs")[-1],
          f"sweep.md: {md[:900]}")

    broken = MODULE.replace("close = metrics", "raise ValueError('broken rule')\n        close = metrics")
    config = write_experiment(context.path("broken"), broken)
    code, output = context.run([dream, "run", config, "--out", context.path("broken", "run")], timeout=120)
    summary = read_summary(context.path("broken", "run"))
    error = summary["metrics"].get("error", "")
    check("ValueError: broken rule" in error and "pair.py:" in error, f"metrics.error: {error!r}")
    check(code == 5 and not summary["goal"]["met"], f"a failing goal(): exit {code}, goal {summary['goal']}")

    # A goal that cannot be judged is a failure even when --steps cut the run
    # short (a goal that merely was not reached yet is not judged then).
    unusable = MODULE.replace("return [[point] for point in POINTS]", "return [['not', 'a point']]")
    for name, module in (("broken", broken), ("unusable", unusable)):
        config = write_experiment(context.path(name + "_cut"), module)
        run = context.path(name + "_cut", "run")
        code, output = context.run([dream, "run", config, "--out", run, "--steps", "40"], timeout=120)
        summary = read_summary(run)
        goal = [r for r in summary["verdict_reasons"] if r["rule"] == "goal"]
        check(code == 5 and summary["verdict"] == "not_ready" and goal and "could not be judged" in goal[0]["problem"],
              f"{name} goal with --steps 40: exit {code}, verdict {summary['verdict']}, reasons "
              f"{summary['verdict_reasons']}: {output[-400:]}")
        check(summary["goal"].get("judge_error"), f"{name}: summary.json goal.judge_error: {summary['goal']}")
        check("goal: not judged" not in output, f"{name}: must not say the goal was merely not judged: {output[-400:]}")


def test(context, args):
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)  # as on a user's machine
    single_runs(context, args.dream)
    sweeps(context, args.dream)


if __name__ == "__main__":
    main(lambda context: test(context, arguments()))
