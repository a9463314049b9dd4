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

import numpy as np

from rps.utilities.controllers import create_pose_controller_hybrid
from rps.utilities.misc import create_at_pose, generate_initial_poses, generate_random_poses

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


def charger_poses(n, width, height):
    """n charger slots (3 x n) drawn with random.sample from the 22 (misc.generate_initial_poses)."""
    return generate_initial_poses(n, width, height)


def random_poses(n, spacing, width, height):
    """3 x n poses at least `spacing` apart, drawn from numpy's global stream (misc.generate_random_poses)."""
    return generate_random_poses(n, spacing, width, height)


_at_pose = create_at_pose(AT_POSITION, AT_ROTATION)


def at_pose(states, poses):
    """Per robot: within AT_POSITION metres and AT_ROTATION radians of its pose."""
    return _at_pose(states, poses)[1]


def pose_controller():
    """The drive's two-phase pose controller (controllers.create_pose_controller_hybrid with the
    drive's gains). It keeps each robot's phase between calls and resets it whenever it is called
    with another number of robots than the last time; the drive calls it for all robots and for
    single robots in turn, so that matters."""
    return create_pose_controller_hybrid(linear_velocity_gain=LINEAR_VELOCITY_GAIN,
                                         angular_velocity_limit=ANGULAR_VELOCITY_LIMIT,
                                         velocity_magnitude_limit=VELOCITY_MAGNITUDE_LIMIT,
                                         position_error=CONTROLLER_POSITION_ERROR,
                                         position_epsilon=CONTROLLER_POSITION_EPSILON,
                                         rotation_error=CONTROLLER_ROTATION_ERROR)


def one_robot(controller, state, pose):
    return controller(state.reshape(-1, 1), pose.reshape(-1, 1))[:, 0]


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
    controller = pose_controller()
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
                dxu[:, i] = one_robot(controller, x[:, i], waypoints[:, i])
                if moved > DEADLOCK_EPSILON:
                    waypointing[i] = False
                elif stuck_for > DEADLOCK_STEPS:
                    waypoints[:, i] = waypoint_near(x[:, i], robotarium.BOUNDARIES)
                    timers[i] = iteration
            elif stuck_for > DEADLOCK_STEPS and moved < DEADLOCK_EPSILON:
                waypointing[i] = True
                waypoints[:, i] = waypoint_near(x[:, i], robotarium.BOUNDARIES)
                timers[i] = iteration
            elif moved > DEADLOCK_EPSILON or np.linalg.norm(one_robot(controller, x[:, i], targets[:, i])) <= STILL_COMMAND:
                timers[i] = iteration
                last_still[:, i] = x[:, i].copy()
        iteration += 1
        robotarium.set_velocities(ids, barrier(dxu, x))
        robotarium.step()
