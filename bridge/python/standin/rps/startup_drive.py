"""The Robotarium V2 start-up drive for the stand-in: what the official Robotarium(...) does
before the experiment (rps/robotarium.py initialize(), written anew here from its behaviour).

The robots come off randomly chosen charger slots and drive onto their initial conditions with a
two-phase pose controller under the unicycle barrier certificate without boundary; a robot that
moved less than 0.1 m in 150 steps is sent to a random waypoint within 0.25 m until it has moved
0.1 m; the drive ends when every robot is within 0.05 m and 0.2 rad of its pose. It draws from
Python's `random` (the placement) and numpy's global stream (the unused first waypoints, the
waypoints, and, in the Robotarium's step, the sensors' noise) the same numbers in the same order
as the official simulator, so a seeded script takes the official drive step for step. DREAM's C++
twin, world::StartupDrive (sim/world/), drives the same way from its own random stream.
"""

import math
import random

import numpy as np

CHARGER_SLOTS_PER_EDGE = 11
# rps's initialize(): pose controller gains, at-pose tolerances, deadlock rule.
ANGULAR_VELOCITY_LIMIT = math.pi / 3.0
LINEAR_VELOCITY_GAIN = 0.8
VELOCITY_MAGNITUDE_LIMIT = 0.15
CONTROLLER_POSITION_ERROR = 0.05
CONTROLLER_POSITION_EPSILON = 0.03
CONTROLLER_ROTATION_ERROR = 0.1
AT_POSITION = 0.05
AT_ROTATION = 0.2
DEADLOCK_STEPS = 5 * 30
DEADLOCK_EPSILON = 0.1
WAYPOINT_REACH = 0.25
STILL_COMMAND = 0.1
# The area rps draws random poses in (default initial conditions, first waypoints).
RANDOM_POSE_WIDTH = 2.75
RANDOM_POSE_HEIGHT = 1.75
RANDOM_POSE_ATTEMPTS = 10000


def charger_poses(n, width, height):
    """n charger slots (3 x n) drawn with random.sample from the 22 (x left to right; at each x
    the bottom slot, facing up, then the top one, facing down)."""
    slots = []
    for x in np.linspace(-width / 2, width / 2, CHARGER_SLOTS_PER_EDGE, endpoint=True):
        for y in (-height / 2, height / 2):
            slots.append([x, y, np.pi / 2 if y < 0 else -np.pi / 2])
    return np.array(random.sample(slots, n)).T


def random_poses(n, spacing, width, height):
    """3 x n poses at least `spacing` apart, uniform in a width x height rectangle about the
    origin, by rejection from numpy's global stream (as rps's generate_random_poses draws)."""
    capacity = int(np.floor((width * height) / (spacing ** 2)))
    if n > capacity:
        raise AssertionError("Cannot fit %d poses with spacing %.2f m into a %.2f x %.2f m area. Approximate "
                             "maximum: %d." % (n, spacing, width, height, capacity))
    points = []
    attempts = 0
    while attempts < RANDOM_POSE_ATTEMPTS and len(points) < n:
        attempts += 1
        x = (np.random.rand() - 0.5) * width
        y = (np.random.rand() - 0.5) * height
        candidate = np.array([x, y])
        if not points or np.all(np.linalg.norm(np.array(points) - candidate, axis=1) >= spacing):
            points.append(candidate)
    if len(points) != n:
        raise AssertionError("Could not place %d poses with spacing %.2f m after %d attempts. Try reducing N or "
                             "Spacing." % (n, spacing, RANDOM_POSE_ATTEMPTS))
    poses = np.zeros((3, n))
    poses[:2, :] = np.array(points).T
    poses[2, :] = np.random.rand(n) * 2 * np.pi - np.pi
    return poses


def wrap(angle):
    return np.arctan2(np.sin(angle), np.cos(angle))


def at_pose(states, poses):
    """Per robot: within AT_POSITION metres and AT_ROTATION radians of its pose."""
    close = np.linalg.norm(states[:2, :] - poses[:2, :], axis=0) <= AT_POSITION
    turned = np.abs(wrap(states[2, :] - poses[2, :])) <= AT_ROTATION
    return close & turned


class HybridPoseController:
    """Approach the goal's position (single integrator to unicycle), then turn on the spot.

    One 'approaching' flag per robot lives between calls and is reset (all approaching) whenever
    the controller is called with another number of robots than the last time, as rps's closure
    does; the drive calls it for all robots and for single robots in turn, so that matters."""

    def __init__(self):
        self.approaching = np.array([])

    def __call__(self, states, poses):
        n = states.shape[1]
        if self.approaching.shape[0] != n:
            self.approaching = np.ones(n)
        dxu = np.zeros((2, n))
        for i in range(n):
            offset = poses[:2, i] - states[:2, i]
            distance = np.linalg.norm(offset)
            heading_error = wrap(poses[2, i] - states[2, i])
            if self.approaching[i] and distance > CONTROLLER_POSITION_ERROR - CONTROLLER_POSITION_EPSILON:
                if distance > VELOCITY_MAGNITUDE_LIMIT:
                    offset = VELOCITY_MAGNITUDE_LIMIT * offset / distance
                heading = states[2, i]
                forward = np.dot(np.array([np.cos(heading), np.sin(heading)]), offset)
                left = np.dot(np.array([-np.sin(heading), np.cos(heading)]), offset)
                dxu[0, i] = LINEAR_VELOCITY_GAIN * forward
                dxu[1, i] = ANGULAR_VELOCITY_LIMIT * np.arctan2(left, forward) / (np.pi / 2)
            elif np.abs(heading_error) > CONTROLLER_ROTATION_ERROR:
                self.approaching[i] = 1 if distance > CONTROLLER_POSITION_ERROR else 0
                dxu[1, i] = 2 * heading_error
        return dxu

    def one(self, state, pose):
        return self(state.reshape(-1, 1), pose.reshape(-1, 1))[:, 0]


def deadlock_watched(at):
    """The robots the deadlock rule looks after. rps picks them with np.isin(indices, at_pose_mask),
    which compares indices with True (1) and False (0): robot 0 only while every robot is on its
    pose, robot 1 only while none is, every robot from 2 on always. Kept: it is the drive's."""
    n = at.shape[0]
    watched = [i for i in range(2, n)]
    if n > 0 and bool(np.all(at)):
        watched.insert(0, 0)
    if n > 1 and not bool(np.any(at)):
        watched.insert(1 if watched[:1] == [0] else 0, 1)
    return watched


def waypoint_near(pose, boundaries):
    """A waypoint within WAYPOINT_REACH of `pose` (clipped to the arena) and a random heading;
    three uniform draws as rps makes them (low above high: numpy takes low + (high - low) u)."""
    x = np.random.uniform(low=min(pose[0] + WAYPOINT_REACH, boundaries[1]),
                          high=max(pose[0] - WAYPOINT_REACH, boundaries[0]))
    y = np.random.uniform(low=min(pose[1] + WAYPOINT_REACH, boundaries[3]),
                          high=max(pose[1] - WAYPOINT_REACH, boundaries[2]))
    theta = np.random.uniform(low=-np.pi, high=np.pi)
    return np.array([x, y, theta])


def drive(robotarium, targets, barrier):
    """Drives `robotarium` (its get_poses / set_velocities / step) onto `targets` (3 x N)."""
    n = robotarium.number_of_robots
    controller = HybridPoseController()
    ids = np.arange(n)
    x = robotarium.get_poses()
    iteration = 0
    timers = np.zeros(n, dtype=int)
    last_still = x.copy()
    waypointing = np.zeros(n, dtype=bool)
    # The official drive draws a first set of waypoints it never uses: the draws keep numpy's stream.
    waypoints = random_poses(n, 0.4, RANDOM_POSE_WIDTH, RANDOM_POSE_HEIGHT)
    robotarium.step()
    while not bool(np.all(at_pose(x, targets))):
        x = robotarium.get_poses()
        dxu = controller(x, targets)
        for i in deadlock_watched(at_pose(x, targets)):
            moved = np.linalg.norm(last_still[:2, i] - x[:2, i])
            stuck_for = iteration - timers[i]
            if waypointing[i]:
                dxu[:, i] = controller.one(x[:, i], waypoints[:, i])
                if moved > DEADLOCK_EPSILON:
                    waypointing[i] = False
                elif stuck_for > DEADLOCK_STEPS:
                    waypoints[:, i] = waypoint_near(x[:, i], robotarium.BOUNDARIES)
                    timers[i] = iteration
            elif stuck_for > DEADLOCK_STEPS and moved < DEADLOCK_EPSILON:
                waypointing[i] = True
                waypoints[:, i] = waypoint_near(x[:, i], robotarium.BOUNDARIES)
                timers[i] = iteration
            elif moved > DEADLOCK_EPSILON or np.linalg.norm(controller.one(x[:, i], targets[:, i])) <= STILL_COMMAND:
                timers[i] = iteration
                last_still[:, i] = x[:, i].copy()
        iteration += 1
        robotarium.set_velocities(ids, barrier(dxu, x))
        robotarium.step()
