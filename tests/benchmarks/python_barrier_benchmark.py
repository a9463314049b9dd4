#!/usr/bin/python3
"""How long one step of the unicycle barrier certificate with boundary takes in Python (a
benchmark, not a test): dream.barriers beside rps's own create_uni_barrier_certificate_with_boundary
when --official names a robotarium_python_simulator checkout (or ROBOTARIUM_PYTHON_SIMULATOR does).

The states are barrier_benchmark's (tests/benchmarks/barrier_benchmark.cc): N robots on a circle
driving at full speed towards its far side, where every pair's constraint is close to binding.
Prints, per N and radius, the median CPU time per step over --repeats rounds of --steps steps,
and the largest difference between the two implementations' commands. Target (issue 36): a
20-robot step under 2 ms.

  /usr/bin/python3 tests/benchmarks/python_barrier_benchmark.py [--official DIR] [--repeats 5]
"""

import argparse
import importlib
import math
import os
import statistics
import sys
import time
import warnings

import numpy as np

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE_DIR, "python"))

from dream import barriers  # noqa: E402


def circle_swap_state(n, radius_m):
    """barrier_benchmark's CircleSwapState: roughly inwards at full speed, a little turning."""
    angles = 2 * math.pi * np.arange(n) / n
    poses = np.vstack([radius_m * np.cos(angles), radius_m * np.sin(angles),
                       angles + math.pi + 0.3 * np.sin(3.0 * np.arange(n))])
    commands = np.vstack([np.full(n, 0.2), 0.5 * np.cos(2.0 * np.arange(n))])
    return commands, poses


def cpu_ms_per_step(certificate, commands, poses, steps, repeats):
    rounds = []
    for _ in range(repeats):
        start = time.process_time()
        for _ in range(steps):
            certificate(commands, poses)
        rounds.append((time.process_time() - start) / steps * 1e3)
    return statistics.median(rounds)


def official_certificate(checkout):
    if not checkout:
        return None
    sys.path.insert(0, os.path.abspath(checkout))
    module = importlib.import_module("rps.utilities.barrier_certificates")
    return module.create_uni_barrier_certificate_with_boundary()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--official", default=os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", ""),
                        help="a robotarium_python_simulator checkout to compare with")
    parser.add_argument("--steps", type=int, default=50, help="steps per round (default 50)")
    parser.add_argument("--repeats", type=int, default=5, help="rounds; the median is printed (default 5)")
    args = parser.parse_args()
    ours = barriers.create_uni_barrier_certificate_with_boundary()
    theirs = official_certificate(args.official)
    print("robots  radius_m  dream.barriers_ms  official_ms  max_difference")
    for n, radius_m in ((2, 0.7), (10, 0.7), (20, 0.7), (20, 0.45)):
        commands, poses = circle_swap_state(n, radius_m)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            dream_ms = cpu_ms_per_step(ours, commands, poses, args.steps, args.repeats)
            official_ms, difference = float("nan"), float("nan")
            if theirs is not None:
                official_ms = cpu_ms_per_step(theirs, commands, poses, args.steps, args.repeats)
                difference = float(np.max(np.abs(ours(commands, poses) - theirs(commands, poses))))
        print("%6d  %8.2f  %17.2f  %11.2f  %14.2g" % (n, radius_m, dream_ms, official_ms, difference))
    return 0


if __name__ == "__main__":
    sys.exit(main())
