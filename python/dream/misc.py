"""The Robotarium V2 helpers of rps.utilities.misc, written for DREAM from their definitions: start
poses (the charger slots, random well-spaced poses: the same draws from Python's `random` and
numpy's global stream in the same order, so a seeded script gets the same poses), at-pose checks,
rotation matrices and file names (tests/python/test_toolbox.py holds them to the official ones)."""

import random
from datetime import datetime

import numpy as np

from .toolbox_checks import ToolboxArgumentError, pair, positive, whole, wrap

CHARGER_SLOTS_PER_EDGE = 11
RANDOM_POSE_ATTEMPTS = 10000

# Who hears every at_pose/at_position check a script makes: `dream run SCRIPT.py`'s Robotarium,
# which takes the script's last check as the run's goal (docs/robotarium-scripts.md#the-goal).
_check_listeners = []


def listen_to_checks(listener):
    """listener(check, states, targets, position_error, rotation_error) after every check made by a
    create_at_pose/create_at_position function; check is "at_pose" or "at_position", rotation_error
    None for at_position. Nothing is returned to the check: the script's numbers stay the official."""
    _check_listeners.append(listener)


def _tell_listeners(check, states, targets, position_error, rotation_error):
    for listener in _check_listeners:
        listener(check, states, targets, position_error, rotation_error)


def determine_font_size(robotarium_instance, font_height_meters):
    """The font size in points whose letters are font_height_meters tall in the figure."""
    figure = getattr(robotarium_instance, "_fig", None)
    if figure is None:
        raise ToolboxArgumentError("determine_font_size: this Robotarium has no figure (show_figure=False); "
                                   "DREAM draws runs in `dream view`, not in a matplotlib figure")
    figure.canvas.draw()
    arena_height = robotarium_instance.BOUNDARIES[3] - robotarium_instance.BOUNDARIES[2]
    return figure.get_size_inches()[1] * figure.dpi * (font_height_meters / arena_height)


def generate_initial_poses(N, width=3.0, height=1.0):
    """N of the 22 charger slots the lab's robots leave from, drawn with random.sample: 11 along
    each long edge, facing into the arena (x left to right; at each x the bottom slot, then the
    top one)."""
    N = whole("generate_initial_poses", "N", N, 1)
    slots = [[x, y, np.pi / 2 if y < 0 else -np.pi / 2]
             for x in np.linspace(-width / 2, width / 2, CHARGER_SLOTS_PER_EDGE, endpoint=True)
             for y in (-height / 2, height / 2)]
    if N > len(slots):
        raise ToolboxArgumentError("generate_initial_poses: N must be at most %d (the charger slots), got %d" %
                                   (len(slots), N))
    return np.array(random.sample(slots, N)).T


def _spaced_points(function, what, N, spacing, width, height):
    N = whole(function, "N", N, 1)
    positive(function, "spacing", spacing)
    positive(function, "width", width)
    positive(function, "height", height)
    capacity = int(np.floor((width * height) / (spacing ** 2)))
    if N > capacity:
        raise ToolboxArgumentError("%s: cannot fit %d %s with spacing %.2f m into a %.2f x %.2f m area. Approximate "
                                   "maximum: %d." % (function, N, what, spacing, width, height, capacity))
    points = []
    for _ in range(RANDOM_POSE_ATTEMPTS):
        if len(points) == N:
            break
        candidate = np.array([(np.random.rand() - 0.5) * width, (np.random.rand() - 0.5) * height])
        if not points or np.all(np.linalg.norm(np.array(points) - candidate, axis=1) >= spacing):
            points.append(candidate)
    if len(points) != N:
        raise ToolboxArgumentError("%s: could not place %d %s with spacing %.2f m after %d attempts. Try reducing N "
                                   "or spacing." % (function, N, what, spacing, RANDOM_POSE_ATTEMPTS))
    return np.array(points).T


def generate_random_poses(N, spacing=0.5, width=3.0, height=1.8):
    """N poses at least `spacing` apart, uniform in a width x height rectangle about the origin
    (by rejection), headings uniform in [-pi, pi)."""
    positions = _spaced_points("generate_random_poses", "poses", N, spacing, width, height)
    poses = np.zeros((3, positions.shape[1]))
    poses[:2, :] = positions
    poses[2, :] = np.random.rand(positions.shape[1]) * 2 * np.pi - np.pi
    return poses


def generate_random_positions(N, spacing=0.5, width=3.0, height=1.8):
    """As generate_random_poses, positions only (2 x N)."""
    return _spaced_points("generate_random_positions", "positions", N, spacing, width, height)


def create_at_pose(position_error=0.05, rotation_error=0.2):
    """check(states, poses) -> (every robot there, which robots are): within position_error metres
    and rotation_error radians of its pose."""

    def check_at_pose(states, poses):
        states, poses = pair("check_at_pose", "states", states, 3, "poses", poses, 3)
        close = np.linalg.norm(states[:2, :] - poses[:2, :], axis=0) <= position_error
        there = close & (np.abs(wrap(states[2, :] - poses[2, :])) <= rotation_error)
        _tell_listeners("at_pose", states, poses, position_error, rotation_error)
        return bool(np.all(there)), there

    return check_at_pose


def create_at_position(position_error=0.05):
    """check(states, positions) -> (every robot there, which robots are): within position_error
    metres of its position."""

    def check_at_position(states, positions):
        states, positions = pair("check_at_position", "states", states, 2, "positions", positions, 2,
                                 first_at_least=True)
        there = np.linalg.norm(states[:2, :] - positions[:2, :], axis=0) <= position_error
        _tell_listeners("at_position", states, positions, position_error, None)
        return bool(np.all(there)), there

    return check_at_position


def rotation_matrix(theta):
    """3 x 3 x N homogeneous rotation matrices, one per angle of theta (a number or an array)."""
    theta = np.atleast_1d(np.asarray(theta, dtype=float)).flatten()
    R = np.zeros((3, 3, len(theta)))
    R[0, 0, :] = np.cos(theta)
    R[0, 1, :] = -np.sin(theta)
    R[1, 0, :] = np.sin(theta)
    R[1, 1, :] = np.cos(theta)
    R[2, 2, :] = 1.0
    return R


def unique_filename(file_name):
    """file_name with the local time appended and .npy: name_YYYY_MM_DD_HH_MM_SS.npy."""
    return "%s_%s.npy" % (file_name, datetime.now().strftime("%Y_%m_%d_%H_%M_%S"))
