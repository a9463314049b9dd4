#!/usr/bin/python3
"""Time per step of an unmodified Robotarium script: under `dream run` against the official simulator
with show_figure=False, same machine, same script (issue 36). A benchmark for docs/performance.md,
not a test.

    tests/integration/netns.sh /usr/bin/python3 tests/benchmarks/script_step_time.py \\
        --dream build/dream --official /tmp/rps [--steps 500] [--repeats 3] [--example REL ...]

Each example of the official package (rps/examples/REL) runs, alternately on each side, under the same
timing wrapper: it forces show_figure=False and sim_in_real_time=False, seeds Python's `random` and
numpy's global stream, and stops the example at its --steps-th experiment step (then debug()). The
time measured is the wall-clock time from the return of the first experiment get_poses() to that
stop, divided by the steps: everything a step costs the script's process and whoever answers it (the official
simulator's step in the same process; DREAM's world in `dream run`, over LCM: udpm, so run it under
tests/integration/netns.sh or with a multicast route). The start-up drive is not timed, nor is the
first experiment step's get_poses() (under `dream run` it waits ~0.2 s for the world to start the
experiment, once, which over 300 steps would add 0.65 ms to each; it is printed on its own), so one
wait for the world of --steps is left out (~0.05 ms, once). The sides run
in --repeats pairs, which side goes first alternating. Prints, per example, the medians over the pairs
of both sides' wall time per step and of the ratio within a pair, the CPU time per step of the
script's own process (all of the official side's work; under `dream run` the script's share, the
world's C++ step and the bus aside), which a loaded machine disturbs far less than wall time, and
under `dream run` the wall time per step the script spent waiting for the world's poses
(WorldLink.next_poses: the world's round trip) and publishing its commands (WorldLink.send: one
DREAM_CMDS message for every robot), both inside the step's time. The load average is printed before and after.
"""

import argparse
import collections
import json
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = ["go_to_goal/go_to_point_si.py", "barrier_certificates/uni_barriers.py",
            "formation_control/formation_control.py", "consensus/consensus_fewer_errors.py"]

TIMING_WRAPPER = r'''
import json, random, runpy, sys, time
import numpy as np
import rps.robotarium as robotarium

EXAMPLE, STEPS, OUT, SEED = {example!r}, {steps}, {out!r}, {seed}
original_init, original_get = robotarium.Robotarium.__init__, robotarium.Robotarium.get_poses
marks = {{"steps": 0, "start": None, "cpu_start": None, "first_seconds": 0.0}}
made = []


class StepCap(BaseException):
    pass


def init(self, **kwargs):
    kwargs["show_figure"] = False
    kwargs["sim_in_real_time"] = False
    original_init(self, **kwargs)


def get_poses(self):
    if self.initializing:
        return original_get(self)
    if marks["start"] is None:  # the first experiment step's poses: the clocks start once they are in
        first = time.perf_counter()
        poses = original_get(self)
        marks["start"], marks["cpu_start"] = time.perf_counter(), time.process_time()
        marks["first_seconds"] = marks["start"] - first
        return poses
    marks["steps"] += 1
    if marks["steps"] == STEPS:
        made.append(self)
        raise StepCap()
    return original_get(self)


robotarium.Robotarium.__init__ = init
robotarium.Robotarium.get_poses = get_poses
link = {{"wait_seconds": 0.0, "send_seconds": 0.0}}
try:  # under `dream run`: the step's time waiting for the world's poses, and publishing the commands
    import rps._world_link as world_link
except ImportError:
    world_link = None
if world_link is not None:
    def timed(name, method):
        def call(*args, **kwargs):
            if marks["start"] is None:
                return method(*args, **kwargs)
            start = time.perf_counter()
            try:
                return method(*args, **kwargs)
            finally:
                link[name] += time.perf_counter() - start
        return call
    world_link.WorldLink.next_poses = timed("wait_seconds", world_link.WorldLink.next_poses)
    world_link.WorldLink.send = timed("send_seconds", world_link.WorldLink.send)
random.seed(SEED)
np.random.seed(SEED)
try:
    runpy.run_path(EXAMPLE, run_name="__main__")
except StepCap:
    pass
seconds = time.perf_counter() - marks["start"]
cpu_seconds = time.process_time() - marks["cpu_start"]
with open(OUT, "w") as f:
    json.dump(dict(link, steps=marks["steps"], seconds=seconds, cpu_seconds=cpu_seconds,
                   first_seconds=marks["first_seconds"]), f)
if made:
    made[0].debug()
'''


def run_side(argv, env, out):
    """The side's wall and CPU ms per step, and under `dream run` its ms per step waiting for the
    world's poses and publishing the commands (0 on the official side), the ms the first experiment
    step's poses took (not timed in the rest); and the steps timed."""
    result = subprocess.run(argv, env=env, capture_output=True, text=True)
    if result.returncode not in (0, 3, 5):  # dream run: 3 rejected, 5 not ready (the verdict), still timed
        sys.exit(f"`{' '.join(argv)}` exited {result.returncode}: {result.stdout[-800:]}{result.stderr[-800:]}")
    with open(out) as f:
        timing = json.load(f)
    steps = max(timing["steps"], 1)
    per_step = [1000.0 * timing[key] / steps for key in ("seconds", "cpu_seconds", "wait_seconds", "send_seconds")]
    return per_step + [1000.0 * timing["first_seconds"]], timing["steps"]


def measure(args, example, folder, index):
    """--repeats pairs of runs, one a side, the side that goes first alternating (so a trend in the
    machine's load weighs on both); the medians per side."""
    name = os.path.splitext(os.path.basename(example))[0]
    path = os.path.join(args.official, "rps", "examples", example)
    times = collections.defaultdict(list)
    steps = 0
    for repeat in range(args.repeats):
        for side in ("official", "dream") if repeat % 2 == 0 else ("dream", "official"):
            out = os.path.join(folder, f"{name}_{side}_{repeat}.json")
            wrapper = os.path.join(folder, f"{name}_{side}_{repeat}.py")
            with open(wrapper, "w") as f:
                f.write(TIMING_WRAPPER.format(example=path, steps=args.steps, out=out, seed=args.seed))
            env = dict(os.environ, MPLBACKEND="Agg")
            if side == "official":
                env["PYTHONPATH"] = args.official
                argv = [sys.executable, wrapper]
            else:
                env["DREAM_PYTHON"] = sys.executable
                argv = [args.dream, "run", wrapper, "--seed", str(args.seed), "-q",
                        "--out", os.path.join(folder, f"run_{index}_{repeat}")]
            (ms, cpu_ms, wait_ms, send_ms, first_ms), steps = run_side(argv, env, out)
            times[side].append(ms)
            times[side + "_cpu"].append(cpu_ms)
            times[side + "_first"].append(first_ms)
            if side == "dream":
                times["dream_wait"].append(wait_ms)
                times["dream_send"].append(send_ms)
        times["ratio"].append(times["dream"][-1] / times["official"][-1])  # within the pair
    return {key: statistics.median(values) for key, values in times.items()}, steps


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--dream", required=True)
    parser.add_argument("--official", default=os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", ""))
    parser.add_argument("--steps", type=int, default=500)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--example", action="append")
    args = parser.parse_args()
    if not os.path.isfile(os.path.join(args.official, "rps", "robotarium.py")):
        sys.exit("--official (or ROBOTARIUM_PYTHON_SIMULATOR) must name a robotarium_python_simulator checkout")
    if not 1 <= args.steps <= 100000 or not 1 <= args.repeats <= 100:
        sys.exit("--steps must be 1..100000 and --repeats 1..100")
    print(f"load average at the start: {os.getloadavg()[0]:.1f}")
    print(f"{'example':45s} {'steps':>6s} {'official ms/step':>17s} {'dream run ms/step':>18s} {'ratio':>6s} "
          f"{'official CPU':>13s} {'script CPU':>11s} {'waits world':>12s} {'publishes':>10s} "
          f"{'first poses: official':>22s} {'dream run':>10s}")
    with tempfile.TemporaryDirectory(prefix="script_step_time_") as folder:
        for index, example in enumerate(args.example or EXAMPLES):
            medians, steps = measure(args, example, folder, index)
            print(f"{example:45s} {steps:6d} {medians['official']:17.2f} {medians['dream']:18.2f} "
                  f"{medians['ratio']:6.2f} {medians['official_cpu']:13.2f} {medians['dream_cpu']:11.2f} "
                  f"{medians['dream_wait']:12.2f} {medians['dream_send']:10.2f} "
                  f"{medians['official_first']:22.1f} {medians['dream_first']:10.1f}", flush=True)
    print(f"load average at the end: {os.getloadavg()[0]:.1f}")

if __name__ == "__main__":
    main()
