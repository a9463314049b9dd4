"""A small pure-Python unicycle world for the Python HRVO circle swap (config/python/hrvo_circle.py),
shared by test_hrvo.py and tests/benchmarks/python_hrvo_benchmark.py.

The world follows sim/world's UnicycleWorld: Euler steps of 0.033 s, each command saturated
per wheel as the Robotarium does (uni -> wheel speeds, clip each to 0.2/0.016 rad/s, back);
the velocities a snapshot carries are those driven during the previous step. A collision is two
robots' centres, or their collision centres 0.025 m ahead, closer than 0.135 m; a boundary
error is a step on which some robot's centre is outside the arena. Radio messages sent at step
k are delivered to every other agent, which hears them (range radio) from step k + 1.
"""

import json
import math
import os
import time

import numpy as np

from dream import ControllerSpec, RadioMessage, WorldSnapshot

from unit_setup import SOURCE_DIR  # (beside this file: its importers have it on the path)

MODULE = os.path.join(SOURCE_DIR, "config", "python", "hrvo_circle.py")

STEP_S = 0.033
WHEEL_RADIUS_M = 0.016
BASE_LENGTH_M = 0.11
MAX_WHEEL_SPEED_RADPS = 0.2 / 0.016
COLLISION_DIAMETER_M = 0.135
COLLISION_OFFSET_M = 0.025
ARENA = (-1.6, 1.6, -1.0, 1.0)


def circle_spec(num_robots, seed=1, params=None):
    """A controller spec (docs/python-runtime-contract.md) for the circle swap with
    config/hrvo_circle.yaml's parts: Appendix B's timers and a range radio every 30 steps."""
    odd = [i % 2 for i in range(num_robots)]
    params = {"radius_m": 0.85, "formations": 3, "tolerance_m": 0.05, "max_speed_mps": 0.2,
              "hrvo": {"variant": "exact", "safety_radius_m": 0.24}} if params is None else params
    return {
        "format": 1, "name": "hrvo_circle_python", "config_file": "config/hrvo_circle_python.yaml",
        "robots": num_robots, "seed": seed, "module": MODULE, "class": "HrvoCircleRobot", "section_line": 1,
        "module_line": 2, "class_line": 3,
        "params": {name: {"value": value, "line": 1} for name, value in params.items()},
        "parts": {
            "robot": {"period_steps": [4 + o for o in odd], "start_delay_steps": [20 + i for i in range(num_robots)],
                      "vel_gain": 0.8, "ang_gain": 3.0},
            "sensors": [{"kind": "odometry", "period_steps": [2 + o for o in odd], "noise_std": 0.0},
                        {"kind": "movement", "period_steps": [3 + o for o in odd], "range_m": 1.0,
                         "direction_rad": 0.0, "field_of_view_rad": 2.0 * math.pi, "noise_std": 0.0}],
            "radio": {"kind": "range", "period_steps": [30] * num_robots, "range_m": 1.0, "graph": [[0.0]],
                      "leaders": [], "loss_probability": 0.0, "delay_steps": 0},
        },
    }


def circle_agents(num_robots, seed=1, params=None):
    spec = ControllerSpec.from_json(json.dumps(circle_spec(num_robots, seed, params)))
    return [spec.make_agent(i) for i in range(num_robots)]


def start_poses(num_robots, seed, min_spacing_m=0.3, wall_margin_m=0.15):
    """Random collision-free start poses as config/hrvo_circle.yaml asks for them
    (initial_poses.generate): centres min_spacing_m apart, wall_margin_m inside the arena."""
    rng = np.random.default_rng(seed)
    poses = []
    while len(poses) < num_robots:
        x = rng.uniform(ARENA[0] + wall_margin_m, ARENA[1] - wall_margin_m)
        y = rng.uniform(ARENA[2] + wall_margin_m, ARENA[3] - wall_margin_m)
        if all(math.hypot(x - p[0], y - p[1]) >= min_spacing_m for p in poses):
            poses.append([x, y, rng.uniform(-math.pi, math.pi)])
    return poses


class RunResult:
    """What a run came to: steps run, whether every robot was done, violation counts, the
    closest two centres came, and the wall time spent in the agents' step() calls."""

    def __init__(self):
        self.steps = 0
        self.all_done = False
        self.collisions = 0
        self.boundary_errors = 0
        self.min_distance_m = math.inf
        self.controller_seconds = 0.0
        self.total_seconds = 0.0


def saturate(v, w):
    """The Robotarium's _threshold: (v, w) -> wheel speeds, each clipped, -> (v, w)."""
    inverse_two_radius = 1.0 / (2.0 * WHEEL_RADIUS_M)
    left = inverse_two_radius * (2.0 * v - BASE_LENGTH_M * w)
    right = inverse_two_radius * (2.0 * v + BASE_LENGTH_M * w)
    left = max(-MAX_WHEEL_SPEED_RADPS, min(MAX_WHEEL_SPEED_RADPS, left))
    right = max(-MAX_WHEEL_SPEED_RADPS, min(MAX_WHEEL_SPEED_RADPS, right))
    return (WHEEL_RADIUS_M / 2.0) * (left + right), (WHEEL_RADIUS_M / BASE_LENGTH_M) * (right - left)


def run(agents, poses, max_steps):
    """Steps the world with `agents` from `poses` ([x, y, theta] lists) until every agent is
    done or max_steps have run. Returns a RunResult."""
    result = RunResult()
    num_robots = len(agents)
    poses = [list(p) for p in poses]
    velocities = [[0.0, 0.0] for _ in range(num_robots)]
    pairs = np.triu_indices(num_robots, 1)
    x_min, x_max, y_min, y_max = ARENA
    clock = time.perf_counter
    started = clock()
    for step in range(max_steps):
        snapshot = WorldSnapshot(step, poses, velocities)
        tick = clock()
        outputs = [agent.step(snapshot) for agent in agents]
        for sender, output in enumerate(outputs):
            if output.broadcast is not None:
                message = RadioMessage(sender, step, output.broadcast)
                for agent in agents:
                    agent.receive(message)
        result.controller_seconds += clock() - tick
        result.steps = step + 1
        if all(output.done for output in outputs):
            result.all_done = True
            break
        outside = False
        for pose, velocity, output in zip(poses, velocities, outputs):
            x, y, theta = pose
            outside = outside or x < x_min or x > x_max or y < y_min or y > y_max
            v, w = saturate(output.v, output.w)
            velocity[0] = v
            velocity[1] = w
            pose[0] = x + STEP_S * v * math.cos(theta)
            pose[1] = y + STEP_S * v * math.sin(theta)
            theta += STEP_S * w
            pose[2] = math.atan2(math.sin(theta), math.cos(theta))
        result.boundary_errors += outside
        state = np.array(poses)
        centres = state[:, :2]
        ahead = centres + COLLISION_OFFSET_M * np.column_stack((np.cos(state[:, 2]), np.sin(state[:, 2])))
        distance = np.hypot(*(centres[pairs[0]] - centres[pairs[1]]).T)
        ahead_distance = np.hypot(*(ahead[pairs[0]] - ahead[pairs[1]]).T)
        result.min_distance_m = min(result.min_distance_m, float(distance.min()))
        result.collisions += int(np.count_nonzero((distance < COLLISION_DIAMETER_M)
                                                  | (ahead_distance < COLLISION_DIAMETER_M)))
    result.total_seconds = clock() - started
    return result
