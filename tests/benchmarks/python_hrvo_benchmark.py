#!/usr/bin/python3
"""How fast the Python HRVO circle swap runs in one Python process (a benchmark, not a test).

Runs config/python/hrvo_circle.py's robots (built through dream.ControllerSpec with the thesis's
timers, as config/hrvo_circle_python.yaml) in the pure-Python world of
tests/python/hrvo_circle_world.py until every robot has finished its three formations, and
prints one row per run: steps, whether all finished, collisions, steps/s of the whole loop
(world included), ms per step in the agents' step() calls, and us per HRVO solve. Targets
(issue 9): 10 robots > 400 steps/s; 20 robots < 10 ms of controller work per step.

For comparison the same robots run with the thesis's sampled HRVO, twice: dream.hrvo's port
(`hrvo: {variant: thesis}`), and the thesis's own code (agents/hrvo/reference/thesis_hrvo.py,
the numpy transcription of Robot_hrvo.HRVO, fed the thesis's detections [dist, angle from the
neighbour, vx, vy]). The thesis's whole experiment (Robotarium simulator and plotting
included) ran at ~180 steps/s (docs/performance.md).

  /usr/bin/python3 tests/benchmarks/python_hrvo_benchmark.py [--seed 1] [--max-steps 6000]
"""

import argparse
import importlib.util
import math
import os
import sys
import time

import numpy as np

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE_DIR, "python"))
sys.path.insert(0, os.path.join(SOURCE_DIR, "tests", "python"))

import hrvo_circle_world  # noqa: E402

THESIS_HRVO = os.path.join(SOURCE_DIR, "agents", "hrvo", "reference", "thesis_hrvo.py")


class ThesisHrvo:
    """The thesis's HRVO behind HrvoAvoidance.solve's signature. Where the thesis raises
    IndexError (a neighbour other than the last removes every sample) it returns zero, as the
    C++ HrvoThesis does."""

    def __init__(self, params, thesis):
        self.params = params
        self._thesis = thesis

    def solve(self, pos_x, pos_y, current_x, current_y, preferred_x, preferred_y, neighbours):
        detections = [[math.sqrt(rx * rx + ry * ry), math.atan2(-ry, -rx), vx, vy] for rx, ry, vx, vy in neighbours]
        try:
            out = self._thesis.hrvo(np.array((pos_x, pos_y)), np.array((current_x, current_y)), detections,
                                    np.array((preferred_x, preferred_y)), safety=self.params.safety_radius_m,
                                    check_boundaries=self.params.check_boundaries)
        except IndexError:
            return 0.0, 0.0
        return float(out[0]), float(out[1])


class TimedHrvo:
    """Counts and times the solves of the avoidance it wraps."""

    def __init__(self, inner):
        self.inner = inner
        self.params = inner.params
        self.calls = 0
        self.seconds = 0.0

    def solve(self, *args):
        started = time.perf_counter()
        answer = self.inner.solve(*args)
        self.seconds += time.perf_counter() - started
        self.calls += 1
        return answer


def load_thesis():
    spec = importlib.util.spec_from_file_location("thesis_hrvo", THESIS_HRVO)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def run(num_robots, seed, max_steps, variant="exact", thesis=None):
    """One circle swap; `thesis`: the thesis_hrvo module, whose HRVO then replaces dream's."""
    params = {"radius_m": 0.85, "formations": 3, "tolerance_m": 0.05, "max_speed_mps": 0.2,
              "hrvo": {"variant": variant, "safety_radius_m": 0.24}}
    agents = hrvo_circle_world.circle_agents(num_robots, seed=seed, params=params)
    timers = []
    for agent in agents:
        inner = agent.robot.hrvo if thesis is None else ThesisHrvo(agent.robot.hrvo.params, thesis)
        agent.robot.hrvo = TimedHrvo(inner)
        timers.append(agent.robot.hrvo)
    result = hrvo_circle_world.run(agents, hrvo_circle_world.start_poses(num_robots, seed), max_steps)
    calls = sum(t.calls for t in timers)
    name = "thesis (thesis_hrvo.py)" if thesis else f"{variant} (dream.hrvo)"
    return {"robots": num_robots, "hrvo": name,
            "steps": result.steps, "done": "yes" if result.all_done else "no", "collisions": result.collisions,
            "steps_per_s": result.steps / result.total_seconds,
            "controller_ms": 1000.0 * result.controller_seconds / result.steps,
            "solves_per_step": calls / result.steps,
            "us_per_solve": 1e6 * sum(t.seconds for t in timers) / max(calls, 1)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1, help="start poses' seed (default 1)")
    parser.add_argument("--max-steps", type=int, default=6000, help="stop a run after this many steps (default 6000)")
    args = parser.parse_args()
    thesis = load_thesis()
    rows = [run(10, args.seed, args.max_steps), run(20, args.seed, args.max_steps),
            run(10, args.seed, args.max_steps, variant="thesis"), run(20, args.seed, args.max_steps, variant="thesis"),
            run(10, args.seed, args.max_steps, thesis=thesis)]
    print("| robots | HRVO | steps | all done | collisions | steps/s | controller ms/step | solves/step | us/solve |")
    print("|---:|---|---:|---|---:|---:|---:|---:|---:|")
    for row in rows:
        print(f"| {row['robots']} | {row['hrvo']} | {row['steps']} | {row['done']} | {row['collisions']} | "
              f"{row['steps_per_s']:.0f} | {row['controller_ms']:.3f} | {row['solves_per_step']:.2f} | "
              f"{row['us_per_solve']:.0f} |")


if __name__ == "__main__":
    main()
