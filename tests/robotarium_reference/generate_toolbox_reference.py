#!/usr/bin/python3
"""Record the official Robotarium V2 toolbox on random inputs: rps.utilities.transformations,
controllers, graph and misc (the barrier certificates have generate_barrier_reference.py).

Usage:
    /usr/bin/python3 generate_toolbox_reference.py <robotarium_python_simulator checkout> [output] [--seed S]

Every case is a call (or a sequence of calls on one created function, for the pose controller
that keeps state between calls) with its inputs and the official outputs; the random functions
(random graphs, random poses, charger slots) are called right after seeding Python's `random` and
numpy's global stream, so their outputs are the draws a seeded script gets. Written as JSON
(default: stdout). tests/python/test_toolbox.py compares dream's toolbox (python/dream/) with
tests/data/robotarium_v2_toolbox.json, and with a fresh run of this when
ROBOTARIUM_PYTHON_SIMULATOR names a checkout. Needs numpy (Debian: /usr/bin/python3).
"""

import argparse
import importlib
import json
import os
import random
import subprocess
import sys

import numpy as np


def encode(value):
    if isinstance(value, np.ndarray):
        kind = "bool" if value.dtype == bool else ("int" if np.issubdtype(value.dtype, np.integer) else "float")
        return {"array": value.tolist(), "dtype": kind, "shape": list(value.shape)}
    if isinstance(value, tuple):
        return {"tuple": [encode(v) for v in value]}
    if isinstance(value, (np.bool_, bool)):
        return bool(value)
    if isinstance(value, (np.integer,)):
        return int(value)
    if isinstance(value, (np.floating,)):
        return float(value)
    return value


def decode(value):
    if isinstance(value, dict) and "array" in value:
        dtype = {"bool": bool, "int": np.int64, "float": float}[value["dtype"]]
        return np.array(value["array"], dtype=dtype).reshape(value["shape"])
    if isinstance(value, dict) and "tuple" in value:
        return tuple(decode(v) for v in value["tuple"])
    return value


def poses(rng, n):
    return np.vstack([rng.uniform(-1.5, 1.5, n), rng.uniform(-0.9, 0.9, n), rng.uniform(-np.pi, np.pi, n)])


def closed_form_cases(rng, count):
    """(module, factory, factory_kwargs, [call args...]) of the deterministic functions."""
    cases = []
    for _ in range(count):
        n = int(rng.integers(1, 12))
        x = poses(rng, n)
        dxi = rng.uniform(-0.3, 0.3, (2, n)) * (rng.random(n) < 0.8)  # some robots at rest
        dxu = np.vstack([rng.uniform(-0.3, 0.3, n), rng.uniform(-4, 4, n)])
        gain, limit, d = float(rng.uniform(0.3, 2)), float(rng.uniform(0.5, 4)), float(rng.uniform(0.01, 0.1))
        cases += [
            ("transformations", "create_si_to_uni_dynamics", {}, [[dxi, x]], None),
            ("transformations", "create_si_to_uni_dynamics",
             {"linear_velocity_gain": gain, "angular_velocity_limit": limit}, [[dxi, x]], None),
            ("transformations", "create_si_to_uni_dynamics_with_backwards_motion",
             {"linear_velocity_gain": gain, "angular_velocity_limit": limit}, [[dxi, x]], None),
            ("transformations", "create_si_to_uni_mapping", {"projection_distance": d}, [[dxi, x]], 0),
            ("transformations", "create_si_to_uni_mapping", {}, [[x]], 1),
            ("transformations", "create_uni_to_si_mapping", {"projection_distance": d}, [[dxu, x]], 0),
            ("transformations", "create_uni_to_si_mapping", {}, [[x, x[:2, :]]], 1),
        ]
        goals = poses(rng, n)
        states = goals + rng.uniform(-0.4, 0.4, goals.shape) * (rng.random(n) < 0.7)
        cases += [
            ("controllers", "create_si_position_controller", {}, [[states[:2], goals[:2]]], None),
            ("controllers", "create_si_position_controller",
             {"x_velocity_gain": gain, "y_velocity_gain": float(rng.uniform(0.3, 2)),
              "velocity_magnitude_limit": float(rng.uniform(0.05, 0.3))}, [[states[:2], goals[:2]]], None),
            ("controllers", "create_uni_position_controller", {"projection_distance": d}, [[states, goals[:2]]], None),
            ("controllers", "create_pose_controller_clf", {}, [[states, goals]], None),
            ("controllers", "create_pose_controller_clf", {"wheel_velocity_limit": float(rng.uniform(1, 12))},
             [[states, goals]], None),
            ("controllers", "create_pose_parking_controller_clf", {}, [[states, goals]], None),
            ("controllers", "create_pose_parking_controller_hybrid", {}, [[states, goals]], None),
        ]
        # The hybrid controller keeps each robot's phase between calls and resets it whenever the
        # number of robots changes: a sequence of calls, one of them on a single robot.
        calls, walk = [], states.copy()
        for step in range(6):
            if step == 3:
                calls.append([walk[:, :1], goals[:, :1]])
            calls.append([walk.copy(), goals])
            walk = walk + 0.3 * (goals - walk) + rng.uniform(-0.01, 0.01, walk.shape)
        cases.append(("controllers", "create_pose_controller_hybrid", {}, calls, None))
        cases += [
            ("misc", "create_at_pose", {}, [[states, goals]], None),
            ("misc", "create_at_pose", {"position_error": 0.3, "rotation_error": 1.0}, [[states, goals]], None),
            ("misc", "create_at_position", {"position_error": 0.2}, [[states, goals[:2]]], None),
        ]
        cases.append(("graph", "delta_disk_neighbors", None, [[x, int(rng.integers(0, n)),
                                                               float(rng.uniform(0, 2))]], None))
    for n in (1, 2, 5, 9):
        cases.append(("graph", "completeGL", None, [[n]], None))
        cases.append(("graph", "lineGL", None, [[max(n, 2)]], None))
        cases.append(("graph", "cycleGL", None, [[max(n, 3)]], None))
    cases.append(("misc", "rotation_matrix", None, [[rng.uniform(-4, 4, 5)], [0.3]], None))
    return cases


def seeded_cases(rng, count):
    """(module, function, args) of the functions that draw from `random` and numpy's global stream."""
    cases = []
    for _ in range(count):
        v = int(rng.integers(1, 10))
        cases += [("graph", "random_connectedGL", [v, int(rng.integers(0, 12))]),
                  ("graph", "randomGL", [v, int(rng.integers(0, 12))]),
                  ("misc", "generate_initial_poses", [int(rng.integers(1, 23))]),
                  ("misc", "generate_random_poses", [int(rng.integers(1, 15))]),
                  ("misc", "generate_random_positions", [int(rng.integers(1, 15)), float(rng.uniform(0.2, 0.6))])]
    cases.append(("misc", "generate_random_poses", [30, 0.5, 2.0, 1.0]))  # over capacity: an error
    return cases


def call_closed_form(toolbox, module, factory, kwargs, calls, pick):
    if kwargs is None:  # a plain function
        return [encode(_result(lambda: getattr(toolbox[module], factory)(*args))) for args in calls]
    made = getattr(toolbox[module], factory)(**kwargs)
    function = made[pick] if pick is not None else made
    return [encode(_result(lambda: function(*args))) for args in calls]


def call_seeded(toolbox, module, function, args, seed):
    random.seed(seed)
    np.random.seed(seed)
    return encode(_result(lambda: getattr(toolbox[module], function)(*args)))


def _result(call):
    try:
        return call()
    except (AssertionError, ValueError):
        return {"error": "raised"}  # AssertionError there, ToolboxArgumentError here


def generate(toolbox, seed, count=12):
    rng = np.random.default_rng(seed)
    out = {"closed_form": [], "seeded": []}
    for module, factory, kwargs, calls, pick in closed_form_cases(rng, count):
        out["closed_form"].append({"module": module, "factory": factory, "kwargs": kwargs, "pick": pick,
                                   "calls": [[encode(a) for a in args] for args in calls],
                                   "results": call_closed_form(toolbox, module, factory, kwargs, calls, pick)})
    for module, function, args in seeded_cases(rng, count):
        seed_of_call = int(rng.integers(0, 2 ** 31))
        out["seeded"].append({"module": module, "function": function, "args": args, "seed": seed_of_call,
                              "result": call_seeded(toolbox, module, function, args, seed_of_call)})
    return out


def official_toolbox(checkout):
    sys.path.insert(0, os.path.abspath(checkout))
    return {name: importlib.import_module("rps.utilities." + name)
            for name in ("transformations", "controllers", "graph", "misc")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("checkout")
    parser.add_argument("output", nargs="?")
    parser.add_argument("--seed", type=int, default=20261202)
    options = parser.parse_args()
    data = generate(official_toolbox(options.checkout), options.seed)
    try:
        commit = subprocess.run(["git", "-C", options.checkout, "rev-parse", "HEAD"], check=True,
                                capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR_COMMIT", "unknown (not a git checkout)")
    data = {"generator": "tests/robotarium_reference/generate_toolbox_reference.py", "seed": options.seed,
            "official_commit": commit, **data}
    text = json.dumps(data, separators=(",", ":")) + "\n"
    if options.output:
        with open(options.output + ".tmp", "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(options.output + ".tmp", options.output)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
