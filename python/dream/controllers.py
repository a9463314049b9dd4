"""The Robotarium V2 controllers (rps.utilities.controllers), written for DREAM from their
definitions: the same functions, arguments, defaults and numbers (tests/python/test_toolbox.py
holds them to the official ones), so a script or a dream.Robot gets what the official toolbox
gives. Each create_* returns a function of all robots' states and goals at once.

    to_pose = dream.controllers.create_pose_controller_hybrid()
    dxu = to_pose(poses, goals)          # 3 x N poses, 3 x N goal poses -> 2 x N (v, w)"""

import numpy as np

from .toolbox_checks import non_negative, pair, positive, wrap
from .transformations import create_si_to_uni_dynamics, create_si_to_uni_mapping


def create_si_position_controller(x_velocity_gain=0.8, y_velocity_gain=0.8, velocity_magnitude_limit=0.15):
    """Proportional to the position error (one gain per axis), each velocity's magnitude capped."""
    name = "create_si_position_controller"
    gains = np.array([positive(name, "x_velocity_gain", x_velocity_gain),
                      positive(name, "y_velocity_gain", y_velocity_gain)], dtype=float).reshape(2, 1)
    limit = non_negative(name, "velocity_magnitude_limit", velocity_magnitude_limit)

    def position_controller_si(states, poses):
        states, poses = pair("position_controller_si", "states", states, 2, "poses", poses, 2)
        dx = gains * (poses - states)
        norms = np.linalg.norm(dx, axis=0)
        over = norms > limit
        dx[:, over] = limit * dx[:, over] / norms[over]
        return dx

    return position_controller_si


def create_uni_position_controller(x_velocity_gain=0.8, y_velocity_gain=0.8, velocity_magnitude_limit=0.15,
                                   projection_distance=0.03):
    """The single-integrator position controller driving a point projection_distance ahead of
    each robot, mapped to unicycle commands."""
    position = create_si_position_controller(x_velocity_gain, y_velocity_gain, velocity_magnitude_limit)
    si_to_uni, uni_to_si = create_si_to_uni_mapping(projection_distance)

    def position_controller_uni(states, poses):
        states, poses = pair("position_controller_uni", "states", states, 3, "poses", poses, 2)
        return si_to_uni(position(uni_to_si(states), poses), states)

    return position_controller_uni


def create_pose_controller_clf(approach_angle_gain=1, desired_angle_gain=2.7, rotation_error_gain=1,
                               wheel_velocity_limit=10.0, wheel_radius=0.016, base_length=0.105):
    """A control Lyapunov function's pose controller: all robots to position and heading at once;
    a command whose wheel speeds exceed wheel_velocity_limit is scaled down as a whole."""
    name = "create_pose_controller_clf"
    gamma = approach_angle_gain
    k = desired_angle_gain
    h = rotation_error_gain
    radius = positive(name, "wheel_radius", wheel_radius)
    base = positive(name, "base_length", base_length)
    wheel_limit = non_negative(name, "wheel_velocity_limit", wheel_velocity_limit)
    inverse = np.linalg.inv(np.array([[radius / 2, radius / 2], [-radius / base, radius / base]]))

    def controller_clf(states, poses):
        states, poses = pair("controller_clf", "states", states, 3, "poses", poses, 3)
        # The position error in the goal's frame.
        c, s = np.cos(poses[2, :]), np.sin(poses[2, :])
        dx, dy = poses[0, :] - states[0, :], poses[1, :] - states[1, :]
        ex, ey = 0.0 + c * dx + s * dy, 0.0 - s * dx + c * dy  # from +0.0, as matmul sums
        e = np.sqrt(ex * ex + ey * ey)  # as rps's np.linalg.norm rounds it (not hypot)
        theta = np.arctan2(ey, ex)
        alpha = wrap(theta - (states[2, :] - poses[2, :]))
        ca, sa = np.cos(alpha), np.sin(alpha)
        small = np.abs(alpha) < 1e-6
        sinc = np.where(small, 1.0, sa / np.where(small, 1.0, alpha))
        v = gamma * e * ca
        w = k * alpha + gamma * (ca * sinc) * (alpha + h * theta)
        # Wheel speeds of (v, w) through rps's inverse of the wheels' matrix (its rounding: a command on the
        # limit is scaled or not as there); scale so the faster stays within the limit.
        wheels = np.abs(0.0 + inverse[:, :1] * v + inverse[:, 1:] * w)
        fastest = np.maximum(wheels[0], wheels[1])
        scale = np.where(fastest > wheel_limit, wheel_limit / np.where(fastest > 0, fastest, 1.0), 1.0)
        return np.vstack([v * scale, w * scale])

    return controller_clf


def create_pose_controller_hybrid(linear_velocity_gain=0.8, angular_velocity_limit=np.pi, velocity_magnitude_limit=0.15,
                                  position_error=0.03, position_epsilon=0.01, rotation_error=0.05):
    """Two phases per robot: approach the goal's position (the velocity's magnitude capped, mapped
    to unicycle commands), then turn on the spot to its heading. Which phase a robot is in is kept
    between calls (all approach again whenever the number of robots changes), or passed in and
    returned with in_approach_state, as in the official toolbox."""
    si_to_uni = create_si_to_uni_dynamics(linear_velocity_gain, angular_velocity_limit)
    kept = {"approach": np.array([])}

    def controller_hybrid(states, poses, in_approach_state=None):
        states, poses = pair("controller_hybrid", "states", states, 3, "poses", poses, 3)
        n = states.shape[1]
        if in_approach_state is not None:
            approach = in_approach_state
        else:
            if kept["approach"].shape[0] != n:
                kept["approach"] = np.ones(n)
            approach = kept["approach"]
        dxu = np.zeros((2, n))
        for i in range(n):
            offset = poses[:2, i] - states[:2, i]
            distance = np.linalg.norm(offset)
            heading_error = wrap(poses[2, i] - states[2, i])
            if approach[i] and distance > position_error - position_epsilon:
                if distance > velocity_magnitude_limit:
                    offset = velocity_magnitude_limit * offset / distance
                dxu[:, i] = si_to_uni(offset.reshape(2, 1), states[:, i].reshape(3, 1))[:, 0]
            elif np.abs(heading_error) > rotation_error:
                approach[i] = 1 if distance > position_error else 0
                dxu[1, i] = 2 * heading_error
        if in_approach_state is not None:
            return dxu, approach
        return dxu

    return controller_hybrid


def _parking(controller, position_error, rotation_error):
    """controller, with robots already within position_error and rotation_error of their goal
    pose told to stop."""

    def parking(states, poses):
        dxu = controller(states, poses)
        states, poses = np.asarray(states, dtype=float), np.asarray(poses, dtype=float)
        close = np.linalg.norm(states[:2, :] - poses[:2, :], axis=0) < position_error
        dxu[:, close & (np.abs(wrap(states[2, :] - poses[2, :])) < rotation_error)] = 0
        return dxu

    return parking


def create_pose_parking_controller_clf(approach_angle_gain=1, desired_angle_gain=2.7, rotation_error_gain=1,
                                       wheel_velocity_limit=10.0, wheel_radius=0.016, base_length=0.105,
                                       position_error=0.05, rotation_error=0.2):
    """create_pose_controller_clf, with robots already within position_error and rotation_error of
    their goal pose told to stop."""
    return _parking(create_pose_controller_clf(approach_angle_gain, desired_angle_gain, rotation_error_gain,
                                               wheel_velocity_limit, wheel_radius, base_length),
                    position_error, rotation_error)


def create_pose_parking_controller_hybrid(linear_velocity_gain=0.8, angular_velocity_limit=np.pi,
                                          velocity_magnitude_limit=0.15, position_error=0.05, position_epsilon=0.01,
                                          rotation_error=0.2):
    """create_pose_controller_hybrid, with robots already within position_error and rotation_error
    of their goal pose told to stop."""
    return _parking(create_pose_controller_hybrid(linear_velocity_gain, angular_velocity_limit,
                                                  velocity_magnitude_limit, position_error, position_epsilon,
                                                  rotation_error),
                    position_error, rotation_error)
