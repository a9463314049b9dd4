#!/usr/bin/python3
"""python_agents: Python controllers (kind python) run as agents by `dream run`, one process, memq.

1. The same law in Python and in C++ gives the same run: config/go_to_goal_python.yaml (the
   Python GoToGoal) and config/go_to_goal.yaml (the C++ go_to_goal) give identical DREAM_POSES,
   message by message, the same step count, violations and robots done.
   The same for the thesis's HRVO circle swap (config/hrvo_circle_python.yaml and
   config/hrvo_circle.yaml): every robot done, no collision, the same poses at every step.
2. A Python run repeats exactly: two runs of the same config give byte-equal DREAM_POSES.
3. The run folder keeps the controller's module beside config.yaml, at the path the config names;
   a sweep's runs, whose configs live in their own folders, find the module too; the docs show
   the example module as it is.
4. A controller that raises: that robot is marked lost at the step it failed and stops; the
   other robots go on to the end; summary.json's robot_faults names the robot, the step and the
   module's file:line; the printed report says so; exit 4; `dream export` refuses the run,
   naming the robot and the error.
5. Config mistakes stop the run before anything starts (exit 1, no run folder), each naming
   file:line and key: an unknown own key, a bad value of a declared key, a missing module, a
   class that is not in the module, a class that is not a dream.Robot.

Usage: python_agents.py --dream BIN --source DIR --types-dir DIR
"""

import os
import re

from dreamtest import Context, arguments, check, import_types, main, read_events, read_summary

FAULTY_CONTROLLER = '''\
from dream import Robot, key


class Faulty(Robot):
    """Drives straight; robot 2 divides by zero from fail_step on."""
    KEYS = {"fail_step": key(30, kind="int", at_least=0)}

    def update(self, step):
        if self.id == 2 and step >= self.config["fail_step"]:
            return (1.0 / 0.0, 0.0)
        return (0.05, 0.0)
'''

FAULTY_CONFIG = '''\
name: faulty
robots: 4
steps: 120
stop_when_done: false
initial_poses:
  - [-0.9, -0.5, 0.0]
  - [-0.9, 0.0, 0.0]
  - [-0.9, 0.5, 0.0]
  - [-0.3, -0.7, 0.0]
controller:
  kind: python
  module: faulty.py
  class: Faulty
  fail_step: 30
'''


def poses_by_step(log_path, dream):
    """step -> (x, y, theta tuples) of every DREAM_POSES event."""
    poses = {}
    for event in read_events(log_path):
        if event.channel == "DREAM_POSES":
            message = dream.robot_poses_t.decode(event.data)
            poses[message.step] = (tuple(message.x), tuple(message.y), tuple(message.theta))
    return poses


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def test(context, args):
    dream = import_types(args.types_dir)
    source = args.source

    # 1. Python GoToGoal == C++ go_to_goal.
    python_out, cpp_out = context.path("python"), context.path("cpp")
    context.run([args.dream, "run", os.path.join(source, "config/go_to_goal_python.yaml"), "--out", python_out, "-q"],
                timeout=60, expect=0)
    context.run([args.dream, "run", os.path.join(source, "config/go_to_goal.yaml"), "--out", cpp_out, "-q"],
                timeout=60, expect=0)
    python_summary, cpp_summary = read_summary(python_out), read_summary(cpp_out)
    for key in ("end", "steps", "violations", "robots_done", "robots_ever_lost"):
        check(python_summary[key] == cpp_summary[key],
              f"{key}: Python GoToGoal {python_summary[key]} but C++ go_to_goal {cpp_summary[key]}")
    python_poses = poses_by_step(os.path.join(python_out, "run.lcmlog"), dream)
    cpp_poses = poses_by_step(os.path.join(cpp_out, "run.lcmlog"), dream)
    check(len(python_poses) == python_summary["steps"] + 1,
          f"{len(python_poses)} DREAM_POSES for {python_summary['steps']} steps")
    for step, poses in cpp_poses.items():
        check(python_poses.get(step) == poses, f"step {step}: Python and C++ poses differ")
    # The twin declares the kind's goal: the same verdict, step and figures.
    for field in ("met", "completion_step", "detail"):
        check(python_summary["goal"].get(field) == cpp_summary["goal"].get(field),
              f"goal {field}: Python {python_summary['goal'].get(field)!r}, C++ {cpp_summary['goal'].get(field)!r}")
    for name in ("final_max_goal_error_m", "all_arrived_step"):
        check(python_summary["metrics"].get(name) == cpp_summary["metrics"].get(name),
              f"{name}: Python {python_summary['metrics'].get(name)}, C++ {cpp_summary['metrics'].get(name)}")
    check(python_summary["robot_faults"] == {}, f"unexpected robot_faults {python_summary['robot_faults']}")

    # 1b. The thesis's HRVO circle swap in Python (config/python/hrvo_circle.py) and in C++:
    # radio, sensors, timers, HRVO, the same poses at every step.
    circle_python, circle_cpp = context.path("circle_python"), context.path("circle_cpp")
    context.run([args.dream, "run", os.path.join(source, "config/hrvo_circle_python.yaml"), "--out", circle_python,
                 "-q"], timeout=120, expect=0)
    context.run([args.dream, "run", os.path.join(source, "config/hrvo_circle.yaml"), "--out", circle_cpp, "-q"],
                timeout=120, expect=0)
    circle_summary = read_summary(circle_python)
    check(circle_summary["robots_done"] == list(range(10)) and circle_summary["violations"]["collision_errors"] == 0,
          f"the Python circle swap did not finish cleanly: {circle_summary['robots_done']}, "
          f"{circle_summary['violations']}")
    check(poses_by_step(os.path.join(circle_python, "run.lcmlog"), dream) ==
          poses_by_step(os.path.join(circle_cpp, "run.lcmlog"), dream),
          "the Python and C++ HRVO circle swaps differ")
    # The twin declares the kind's goal (issue 37): the same verdict, step and formation figures.
    cpp_circle = read_summary(circle_cpp)
    for field in ("met", "completion_step", "detail"):
        check(circle_summary["goal"].get(field) == cpp_circle["goal"].get(field),
              f"goal {field}: Python circle {circle_summary['goal'].get(field)!r}, C++ {cpp_circle['goal'].get(field)!r}")
    check(circle_summary["goal"].get("met") is True, f"the Python circle swap's goal: {circle_summary['goal']}")
    for name in ("formations_completed", "formation_1_completed_step", "all_formations_completed_step"):
        check(circle_summary["metrics"].get(name) == cpp_circle["metrics"].get(name),
              f"{name}: Python {circle_summary['metrics'].get(name)}, C++ {cpp_circle['metrics'].get(name)}")

    # 2. Deterministic.
    again = context.path("again")
    context.run([args.dream, "run", os.path.join(source, "config/go_to_goal_python.yaml"), "--out", again, "-q"],
                timeout=60, expect=0)
    check(poses_by_step(os.path.join(again, "run.lcmlog"), dream) == python_poses,
          "two runs of the same Python config differ")

    # 3. The module travels with the run folder.
    with open(os.path.join(source, "config/python/go_to_goal.py")) as f, \
            open(os.path.join(python_out, "python/go_to_goal.py")) as g:
        check(f.read() == g.read(), "the run folder's python/go_to_goal.py is not the module that ran")

    # 3a. docs/python-controllers.md shows the example as it is.
    with open(os.path.join(source, "config/python/go_to_goal.py")) as f, \
            open(os.path.join(source, "docs/python-controllers.md")) as g:
        check("```python\n" + f.read() + "```" in g.read(),
              "docs/python-controllers.md does not show config/python/go_to_goal.py as it is")

    # 3b. A sweep's runs keep the module in their own folders (a copy, as dream run keeps one), so
    # a run's config.yaml repeats it even after the module is edited.
    sweep_out = context.path("sweep")
    context.run([args.dream, "sweep", os.path.join(source, "config/go_to_goal_python.yaml"), "--seeds", "1",
                 "--out", sweep_out, "-q"], timeout=120, expect=0)
    run_dir = os.path.join(sweep_out, "runs", "seed1")
    check(read_summary(run_dir)["steps"] == python_summary["steps"],
          "the sweep's run of go_to_goal_python differs from dream run's")
    with open(os.path.join(source, "config/python/go_to_goal.py")) as f, \
            open(os.path.join(run_dir, "python", "go_to_goal.py")) as g:
        check(f.read() == g.read(), "the sweep's run folder holds no copy of the module")
    with open(os.path.join(run_dir, "config.yaml")) as f:
        check(re.search(r"^  module: python/go_to_goal\.py$", f.read(), re.MULTILINE),
              "the sweep run's config.yaml does not name the module's copy beside it")

    # 4. A controller that raises.
    write(context.path("faulty.py"), FAULTY_CONTROLLER)
    config = write(context.path("faulty.yaml"), FAULTY_CONFIG)
    faulty_out = context.path("faulty_out")
    code, output = context.run([args.dream, "run", config, "--out", faulty_out], timeout=60)
    check(code == 4, f"a run with a failed controller exited {code}, expected 4: {output[-400:]}")
    summary = read_summary(faulty_out)
    check(summary["end"] == "finished" and summary["steps"] == 120,
          f"the run did not go on to its end: {summary['end']} after {summary['steps']} steps")
    faults = summary["robot_faults"]
    check(list(faults) == ["2"], f"robot_faults should name robot 2 only: {faults}")
    check(faults["2"].startswith("step 30: ") and "faulty.py:10: in update: ZeroDivisionError" in faults["2"],
          f"the fault does not say step, file:line and error: {faults['2']}")
    check(summary["robots_ever_lost"] == [2], f"robots_ever_lost {summary['robots_ever_lost']}, expected [2]")
    check("robot 2 was lost, its controller failed at step 30" in output and "NOT ready for the Robotarium" in output,
          f"the report does not say it: {output[-400:]}")
    poses = poses_by_step(os.path.join(faulty_out, "run.lcmlog"), dream)
    x_of = lambda step, robot: poses[step][0][robot]
    check(x_of(120, 2) == x_of(31, 2), f"robot 2 moved after it was lost: x {x_of(31, 2)} -> {x_of(120, 2)}")
    check(x_of(120, 0) > x_of(31, 0) + 0.1, "robot 0 stopped when robot 2 failed")
    fault_events = [event for event in read_events(os.path.join(faulty_out, "run.lcmlog"))
                    if event.channel == "DREAM_FAULT_2"]
    check(len(fault_events) == 1, f"{len(fault_events)} DREAM_FAULT_2 events in the log, expected 1")
    check(dream.robot_fault_t.decode(fault_events[0].data).step == 30, "DREAM_FAULT_2 does not carry step 30")

    # ... and such a run is not exported: the lab would run a controller known to fail.
    code, output = context.run([args.dream, "export", faulty_out, "--strategy", "controller",
                                "--out", context.path("faulty_export")], timeout=60)
    check(code == 3, f"dream export of a run with a failed controller exited {code}, expected 3: {output[-300:]}")
    check("lost_robot: robot 2" in output and "faulty.py:10: in update: ZeroDivisionError" in output,
          f"the refusal does not name the robot and the error: {output[-400:]}")
    check(not os.path.exists(context.path("faulty_export", "upload")), "a refused export wrote its files")

    # 5. Config mistakes, each with file:line and key.
    cases = [
        ("fail_step: 30", "fail_step: 30\n  gain: 2", ":15: controller.gain: unknown key"),
        ("fail_step: 30", "fail_step: -3", ":14: controller.fail_step: must be >= 0, got -3"),
        ("module: faulty.py", "module: missing.py", ":12: controller.module: cannot read"),
        ("module: faulty.py", "module: ../faulty.py", ":12: controller.module: '../faulty.py' leaves the config's folder"),
        ("module: faulty.py", "module: faulty.txt", ":12: controller.module: 'faulty.txt' is not a Python module file"),
        ("class: Faulty", "class: Nope", ":13: controller.class:"),
        ("class: Faulty", "class: key", ":13: controller.class:"),
    ]
    for index, (old, new, expected) in enumerate(cases):
        bad = write(context.path(f"bad{index}.yaml"), FAULTY_CONFIG.replace(old, new))
        bad_out = context.path(f"bad_out{index}")
        code, output = context.run([args.dream, "run", bad, "--out", bad_out], timeout=30)
        check(code == 1, f"case {new!r}: exit {code}, expected 1: {output[-300:]}")
        check(bad + expected in output, f"case {new!r}: expected '{bad}{expected}' in: {output[-300:]}")
        check(not os.path.exists(os.path.join(bad_out, "run.lcmlog")), f"case {new!r}: a run was started")


if __name__ == "__main__":
    main(lambda context: test(context, arguments(types_dir=True)))
