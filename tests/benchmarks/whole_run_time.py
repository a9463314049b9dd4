#!/usr/bin/python3
"""Wall time of a whole `dream run` process, against the thesis's Python code.

    tests/benchmarks/whole_run_time.py --build build config/hrvo_circle.yaml

Runs `dream -q run CONFIG --out <temp>` (its own step limit, ending when every
robot is done, as a user runs it) `--repeat` times and prints the best wall
time of the whole process (start-up, the run, metrics, summary.json and
trajectories.png), the loop's steps/s from summary.json, and how many times
faster the whole process is than `--python-steps-per-s` (the thesis's Python
code runs the HRVO circle at about 180 steps/s on the CI machine,
docs/performance.md). Numbers go to docs/performance.md; nothing here is a
pass/fail test.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import time


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config")
    parser.add_argument("--build", default="build")
    parser.add_argument("--repeat", type=int, default=5, help="runs; the best is reported")
    parser.add_argument("--python-steps-per-s", type=float, default=180.0)
    args = parser.parse_args()
    dream = os.path.join(args.build, "dream")
    best_s = None
    loop = None
    with tempfile.TemporaryDirectory() as folder:
        for index in range(args.repeat):
            out = os.path.join(folder, f"run{index}")
            start = time.perf_counter()
            done = subprocess.run([dream, "-q", "run", args.config, "--out", out], capture_output=True, check=False)
            wall_s = time.perf_counter() - start
            if done.returncode != 0:
                sys.exit(f"{dream} run {args.config} exited {done.returncode}:\n{done.stderr.decode()}")
            with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
                summary = json.load(f)
            print(f"run {index + 1}: {wall_s * 1000:.1f} ms, {summary['steps']} steps, "
                  f"loop {summary['steps_per_second']:.0f} steps/s")
            if best_s is None or wall_s < best_s:
                best_s, loop = wall_s, summary
    python_s = loop["steps"] / args.python_steps_per_s
    print(f"best: {best_s * 1000:.1f} ms for {loop['steps']} steps (loop {loop['steps_per_second']:.0f} steps/s, "
          f"{loop['steps'] / loop['steps_per_second'] * 1000:.1f} ms); the thesis's Python at "
          f"{args.python_steps_per_s:.0f} steps/s: {python_s:.2f} s, {python_s / best_s:.0f}x")


if __name__ == "__main__":
    main()
