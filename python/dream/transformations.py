"""The Robotarium V2 maps between single-integrator and unicycle models
(rps.utilities.transformations), written for DREAM from their definitions: the same functions,
arguments and defaults, the same numbers (tests/python/test_toolbox.py holds them to the official
ones). Vectorised over robots; every function takes and returns 2 x N or 3 x N arrays.

    si_to_uni = dream.transformations.create_si_to_uni_dynamics()
    dxu = si_to_uni(dxi, poses)          # 2 x N velocities -> 2 x N (v, w)"""

import numpy as np

from .toolbox_checks import non_negative, pair, positive, rows, wrap


def _headings(states):
    return np.cos(states[2, :]), np.sin(states[2, :])


def _dot(a, x, b, y):
    """a x + b y summed from +0.0 as numpy's dot and matmul sum: a zero velocity gives +0.0, never
    -0.0, so atan2 of it gives 0 and not pi (a robot at rest is not told to turn)."""
    return 0.0 + a * x + b * y


def create_si_to_uni_dynamics(linear_velocity_gain=1, angular_velocity_limit=np.pi):
    """v: the velocity's projection on the heading (times the gain); w: the angle between velocity
    and heading, scaled so that a right angle gives angular_velocity_limit."""
    name = "create_si_to_uni_dynamics"
    gain = positive(name, "linear_velocity_gain", linear_velocity_gain)
    limit = non_negative(name, "angular_velocity_limit", angular_velocity_limit)

    def si_to_uni(dxi, states):
        dxi, states = pair("si_to_uni", "dxi", dxi, 2, "states", states, 3)
        c, s = _headings(states)
        forward = _dot(c, dxi[0, :], s, dxi[1, :])
        left = _dot(-s, dxi[0, :], c, dxi[1, :])
        return np.vstack([gain * forward, limit * np.arctan2(left, forward) / (np.pi / 2)])

    return si_to_uni


def create_si_to_uni_dynamics_with_backwards_motion(linear_velocity_gain=1, angular_velocity_limit=np.pi):
    """As create_si_to_uni_dynamics, but a robot whose wanted direction is more than a right angle
    off its heading drives backwards (its heading taken as turned by pi)."""
    name = "create_si_to_uni_dynamics_with_backwards_motion"
    gain = positive(name, "linear_velocity_gain", linear_velocity_gain)
    limit = non_negative(name, "angular_velocity_limit", angular_velocity_limit)

    def si_to_uni(dxi, states):
        dxi, states = pair("si_to_uni", "dxi", dxi, 2, "states", states, 3)
        off = wrap(np.arctan2(dxi[1, :], dxi[0, :]) - states[2, :])
        ahead = (off > -np.pi / 2) & (off < np.pi / 2)
        heading = np.where(ahead, states[2, :], wrap(states[2, :] + np.pi))
        c, s = np.cos(heading), np.sin(heading)
        v = gain * _dot(c, dxi[0, :], s, dxi[1, :])
        w = limit * np.arctan2(_dot(-s, dxi[0, :], c, dxi[1, :]), v) / (np.pi / 2)
        return np.vstack([np.where(ahead, v, -v), w])

    return si_to_uni


def create_si_to_uni_mapping(projection_distance=0.05):
    """A point projection_distance ahead of each robot moves as a single integrator: returns
    (si_to_uni_dyn(dxi, states) -> dxu, uni_to_si_states(states) -> the points)."""
    d = positive("create_si_to_uni_mapping", "projection_distance", projection_distance)

    def si_to_uni(dxi, states):
        dxi, states = pair("si_to_uni", "dxi", dxi, 2, "states", states, 3)
        c, s = _headings(states)
        # rps's T @ R: its second row is (1/d) * (-sin, cos), rounded as that product rounds.
        return np.vstack([_dot(c, dxi[0, :], s, dxi[1, :]), _dot((1 / d) * -s, dxi[0, :], (1 / d) * c, dxi[1, :])])

    def uni_to_si(states):
        states = rows("uni_to_si", "states", states, 3)
        c, s = _headings(states)
        return states[0:2, :] + d * np.vstack([c, s])

    return si_to_uni, uni_to_si


def create_uni_to_si_mapping(projection_distance=0.05):
    """The inverse pair: returns (uni_to_si_dyn(dxu, states) -> dxi of the projected points,
    si_to_uni_states(uni_states, si_states) -> the robots' positions behind the points)."""
    d = positive("create_uni_to_si_mapping", "projection_distance", projection_distance)

    def uni_to_si(dxu, states):
        dxu, states = pair("uni_to_si", "dxu", dxu, 2, "states", states, 3)
        c, s = _headings(states)
        # rps's R @ T: its second column is d * (-sin, cos), rounded as that product rounds.
        return np.vstack([_dot(c, dxu[0, :], -s * d, dxu[1, :]), _dot(s, dxu[0, :], c * d, dxu[1, :])])

    def si_to_uni(uni_states, si_states):
        uni_states, si_states = pair("si_to_uni", "uni_states", uni_states, 3, "si_states", si_states, 2)
        c, s = _headings(uni_states)
        return si_states[0:2, :] - d * np.vstack([c, s])

    return uni_to_si, si_to_uni
