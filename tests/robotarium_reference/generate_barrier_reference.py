#!/usr/bin/python3
"""Record the official Robotarium V2 barrier certificates on random states.

Usage:
    /usr/bin/python3 generate_barrier_reference.py <robotarium_python_simulator checkout> [output] [--seed S]

Calls the four certificates of rps/utilities/barrier_certificates.py
(create_si_barrier_certificate[_with_boundary],
create_uni_barrier_certificate[_with_boundary]) with their defaults and with
other parameters, on random robot states (some crowded, some at the walls, some
with obstacle points), and writes every input and output to a JSON fixture
(default: stdout). tests/barriers/barriers_test.cc and tests/python/test_barriers.py
compare dream::barriers and dream.barriers with it (1e-5); the
barriers_reference_live test runs this with a fresh seed and the C++ test on
its output. Needs numpy and cvxopt (Debian: /usr/bin/python3 with
python3-numpy and python3-cvxopt).
"""

import argparse
import json
import os
import platform
import subprocess
import sys
import warnings

import numpy as np


def official_commit(checkout):
    try:
        return subprocess.run(["git", "-C", checkout, "rev-parse", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR_COMMIT", "unknown (not a git checkout)")


def random_positions(rng, n, crowd):
    """n points in the arena; `crowd` of them packed into a small patch so barriers bind."""
    x = np.vstack([rng.uniform(-1.5, 1.5, n), rng.uniform(-0.9, 0.9, n)])
    if crowd:
        centre = rng.uniform([-1.2, -0.7], [1.2, 0.7])
        k = min(n, crowd)
        x[:, :k] = centre[:, None] + rng.uniform(-0.2, 0.2, (2, k))
    return x


def case_states(rng, n, kind):
    crowd = int(rng.integers(0, n + 1))
    if kind.startswith("uni"):
        x = np.vstack([random_positions(rng, n, crowd), rng.uniform(-np.pi, np.pi, n)])
        dx = np.vstack([rng.uniform(-0.25, 0.25, n), rng.uniform(-4.0, 4.0, n)])
    else:
        x = random_positions(rng, n, crowd)
        dx = rng.uniform(-0.3, 0.3, (2, n))
    return x, dx


def params_for(rng, function, defaults):
    if defaults:
        return {}
    params = {"safety_radius": float(rng.uniform(0.08, 0.2)), "barrier_gain": float(rng.uniform(20, 300))}
    if function.startswith("create_uni"):
        params["projection_distance"] = float(rng.uniform(0.02, 0.08))
        params["velocity_magnitude_limit"] = float(rng.uniform(0.1, 0.3))
    else:
        params["magnitude_limit"] = float(rng.uniform(0.1, 0.3))
    if function.endswith("with_boundary"):
        params["boundary_points"] = [-1.6, 1.6, -1.0, 1.0] if rng.uniform() < 0.5 else [-1.5, 1.4, -0.95, 0.9]
    return params


def run_case(bc, function, params, x, dx, obstacles):
    kwargs = dict(params)
    if "boundary_points" in kwargs:
        kwargs["boundary_points"] = np.array(kwargs["boundary_points"])
    certificate = getattr(bc, function)(**kwargs)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        if obstacles is not None:
            out = certificate(dx.copy(), x.copy(), obstacles.copy())
        else:
            out = certificate(dx.copy(), x.copy())
    failed = any("QP failed" in str(w.message) for w in caught)
    return out, failed


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("checkout")
    parser.add_argument("output", nargs="?")
    parser.add_argument("--seed", type=int, default=20260402)
    parser.add_argument("--cases", type=int, default=48)
    args = parser.parse_args()
    sys.path.insert(0, args.checkout)
    from rps.utilities import barrier_certificates as bc  # noqa: E402  (the official package)
    import cvxopt  # noqa: E402

    rng = np.random.default_rng(args.seed)
    functions = ["create_si_barrier_certificate", "create_si_barrier_certificate_with_boundary",
                 "create_uni_barrier_certificate", "create_uni_barrier_certificate_with_boundary"]
    cases = []
    failures = 0
    attempts = 0
    while len(cases) < args.cases or (failures == 0 and attempts < 4000):
        attempts += 1
        function = functions[attempts % 4]
        n = int(rng.integers(1, 21)) if attempts % 7 else int(rng.integers(15, 21))
        x, dx = case_states(rng, n, "uni" if "uni" in function else "si")
        params = params_for(rng, function, defaults=attempts % 3 == 0)
        obstacles = None
        if function == "create_uni_barrier_certificate_with_boundary" and attempts % 5 == 0:
            obstacles = random_positions(rng, int(rng.integers(1, 4)), 0)
        out, failed = run_case(bc, function, params, x, dx, obstacles)
        if len(cases) >= args.cases and not failed:
            continue  # searching for one case where the QP fails, as it sometimes does
        failures += failed
        case = {"function": function, "params": params, "x": x.tolist(), "dx": dx.tolist(),
                "expected": np.asarray(out, dtype=float).tolist(), "qp_failed": failed}
        if obstacles is not None:
            case["obstacles"] = obstacles.tolist()
        cases.append(case)
    document = {
        "about": "rps V2 barrier certificates on random states; tests/robotarium_reference/generate_barrier_reference.py",
        "official_commit": official_commit(args.checkout),
        "python": platform.python_version(), "numpy": np.__version__, "cvxopt": cvxopt.__version__,
        "seed": args.seed,
        "cases": cases,
    }
    text = json.dumps(document, indent=1, sort_keys=True) + "\n"
    if args.output:
        with open(args.output + ".part", "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(args.output + ".part", args.output)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
