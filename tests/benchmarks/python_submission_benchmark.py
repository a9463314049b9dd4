#!/usr/bin/python3
"""How long one step of a controller-strategy submission takes, 10 and 20 robots.

    tests/benchmarks/python_submission_benchmark.py --build build [--simulator CHECKOUT]

For N in (10, 20): writes config/hrvo_circle_python.yaml for N robots (Appendix B's timers
extended to N), runs it (`dream run`), exports it (`dream export --strategy controller`),
runs the submission with bridge/python/run_submission.py --skip-initialization in the
stand-in (and in the official simulator when --simulator or $ROBOTARIUM_PYTHON_SIMULATOR
names one), and reads the wall-clock column of dream_result.npy: the time between two
experiment steps is everything the script does in a step -- get_poses, every robot's
controller, radios, set_velocities and the simulator's step. The lab steps every 33 ms; the
target is under 10 ms at 20 robots. A benchmark for docs/performance.md, not a test.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", ".."))


def circle_config(robots, folder):
    """config/hrvo_circle_python.yaml for `robots` robots, its module by absolute path."""
    with open(os.path.join(SOURCE, "config", "hrvo_circle_python.yaml")) as f:
        text = f.read()
    per_robot = lambda first, alternate: "[" + ", ".join(str(first + (i % 2 if alternate else i))
                                                         for i in range(robots)) + "]"
    text = re.sub(r"^robots: \d+", f"robots: {robots}", text, flags=re.M)
    text = re.sub(r"^name: \S+", f"name: circle{robots}", text, flags=re.M)
    text = text.replace("module: python/hrvo_circle.py",
                        "module: " + os.path.join(SOURCE, "config", "python", "hrvo_circle.py"))
    text = re.sub(r"start_delay_steps: \[[^]]*\]", "start_delay_steps: " + per_robot(20, False), text)
    text = re.sub(r"    period_steps: \[[^]]*\]", "    period_steps: " + per_robot(4, True), text)
    text = re.sub(r"kind: odometry, period_steps: \[[^]]*\]", "kind: odometry, period_steps: " + per_robot(2, True),
                  text)
    text = re.sub(r"kind: movement, period_steps: \[[^]]*\]", "kind: movement, period_steps: " + per_robot(3, True),
                  text)
    path = os.path.join(folder, f"circle{robots}.yaml")
    with open(path, "w") as f:
        f.write(text)
    return path


def run(argv):
    result = subprocess.run(argv, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"`{' '.join(argv)}` exited {result.returncode}: {result.stdout[-500:]}{result.stderr[-500:]}")


def step_times_ms(result_path):
    rows = np.load(result_path, allow_pickle=False)
    experiment = rows[rows[:, 0] == 1]
    return np.diff(experiment[:, 2]) * 1000.0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--simulator", default=os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", ""))
    args = parser.parse_args()
    dream = os.path.abspath(os.path.join(args.build, "dream"))
    runner = os.path.join(SOURCE, "bridge", "python", "run_submission.py")
    simulators = [("stand-in", ["--standin"])]
    if args.simulator:
        simulators.append(("official", ["--simulator", args.simulator, "--require-official"]))
    print("| robots | simulator | experiment steps | median ms/step | 95th percentile | max |")
    print("|---:|---|---:|---:|---:|---:|")
    with tempfile.TemporaryDirectory() as folder:
        for robots in (10, 20):
            config = circle_config(robots, folder)
            run_dir, export_dir = os.path.join(folder, f"run{robots}"), os.path.join(folder, f"export{robots}")
            run([dream, "run", config, "--out", run_dir, "-q"])
            run([dream, "export", run_dir, "--strategy", "controller", "--out", export_dir, "-q"])
            for name, options in simulators:
                workdir = os.path.join(folder, f"{name}{robots}")
                run([sys.executable, runner, "--upload", os.path.join(export_dir, "upload"), "--workdir", workdir,
                     "--report", workdir + ".json", "--skip-initialization"] + options)
                times = step_times_ms(os.path.join(workdir, "dream_result.npy"))
                print(f"| {robots} | {name} | {len(times) + 1} | {np.median(times):.2f} | "
                      f"{np.percentile(times, 95):.2f} | {times.max():.2f} |")


if __name__ == "__main__":
    main()
