#!/usr/bin/python3
"""The stand-in Robotarium against the official simulator's recorded behaviour.

    standin_reference.py --source DIR

Replays every scenario of tests/data/robotarium_v2_reference.csv (recorded from the official
V2.0.0 simulator by tests/robotarium_reference/generate_reference.py: out of the arena, collisions,
every kind of wheel saturation, turning through +-pi, 20 robots at random) through the stand-in
in bridge/python/standin, starting exactly at the recorded poses: every get_poses() within
1e-12, the error counts after every step and debug()'s text identical. Runs in CI, where the
official simulator cannot be installed; bridge_official_simulator compares the two directly
when it can.
"""

import argparse
import contextlib
import io
import os
import sys

TOLERANCE = 1e-12


def scenarios(path):
    current = None
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line.startswith("#"):
                continue
            kind, _, rest = line.partition(",")
            if kind == "scenario":
                name, n, steps = rest.split(",")
                current = {"name": name, "n": int(n), "steps": int(steps), "poses": {}, "cmds": {}, "errors": {},
                           "debug": []}
            elif kind == "pose":
                step, robot, x, y, theta = rest.split(",")
                current["poses"].setdefault(int(step), {})[int(robot)] = (float(x), float(y), float(theta))
            elif kind == "cmd":
                step, robot, v, w = rest.split(",")
                current["cmds"].setdefault(int(step), []).append((int(robot), float(v), float(w)))
            elif kind == "errors":
                step, boundary, collision, actuator = rest.split(",")
                current["errors"][int(step)] = (int(boundary), int(collision), int(actuator))
            elif kind == "debug":
                current["debug"].append(rest)
            elif kind == "end":
                yield current


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--source", required=True)
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(args.source, "bridge", "python", "standin"))
    import numpy as np
    import rps
    from rps.robotarium import Robotarium
    assert rps.STANDIN, "imported the official simulator, not the stand-in"

    count = 0
    worst = 0.0
    for scenario in scenarios(os.path.join(args.source, "tests", "data", "robotarium_v2_reference.csv")):
        n = scenario["n"]
        start = np.array([[scenario["poses"][0][i][q] for i in range(n)] for q in range(3)])
        with contextlib.redirect_stdout(io.StringIO()):
            r = Robotarium(number_of_robots=n, show_figure=False, initial_conditions=start,
                           sim_in_real_time=False, skip_initialization=True)
        for k in range(scenario["steps"] + 1):
            poses = r.get_poses()
            for i in range(n):
                expected = scenario["poses"][k][i]
                error = max(abs(poses[q, i] - expected[q]) for q in range(3))
                worst = max(worst, error)
                if error > TOLERANCE:
                    print("FAIL: %s step %d robot %d: pose %s, official %s" % (scenario["name"], k, i,
                                                                           poses[:, i], expected))
                    return 1
            if k == scenario["steps"]:
                break
            for robot, v, w in scenario["cmds"].get(k, []):
                r.set_velocities(np.array([robot]), np.array([[v], [w]]))
            r.step()
            e = r._errors
            counts = (e.get("robots_outside_boundaries", 0), e.get("robots_too_close", 0),
                      e.get("exceeded_actuator_limits", 0))
            if counts != scenario["errors"][k]:
                print("FAIL: %s step %d: errors %s, official %s" % (scenario["name"], k, counts, scenario["errors"][k]))
                return 1
        text = io.StringIO()
        with contextlib.redirect_stdout(text):
            r.debug()
        if text.getvalue()[:-1].split("\n") != scenario["debug"]:  # as the recorder stored it
            print("FAIL: %s: debug() prints\n%s\nofficial:\n%s" % (scenario["name"], text.getvalue(),
                                                                 "\n".join(scenario["debug"])))
            return 1
        count += 1
        print("%s: %d robots, %d steps: poses, error counts and debug() text as recorded" %
              (scenario["name"], n, scenario["steps"]))
    if count != 4:
        print("FAIL: expected 4 scenarios, found %d" % count)
        return 1
    print("PASS: largest pose difference %.3g" % worst)
    return 0


if __name__ == "__main__":
    sys.exit(main())
