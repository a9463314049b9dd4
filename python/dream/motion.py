"""From a desired planar velocity to a unicycle command the wheels can drive.

Mirrors agents/src/robot.cc (Robot::DxiToDxu), agents/src/actuator_limits.cc and
agents/src/single_integrator_to_unicycle.cc term for term, so that a Python controller
commands the same (v, w) as its C++ twin. Commands are plain (v m/s, w rad/s) tuples:
cheaper than numpy arrays for two numbers, and what `Robot.update` returns.
"""

import math

HALF_PI = math.pi / 2.0


class RobotLimits:
    """The physical limits of a Robotarium GRITSBot X (agents/include/dream/agents/framework/robot_limits.h)."""

    __slots__ = ("max_linear_speed_mps", "wheel_radius_m", "base_length_m", "max_wheel_speed_radps",
                 "max_angular_speed_radps")

    def __init__(self):
        self.max_linear_speed_mps = 0.2
        self.wheel_radius_m = 0.016
        self.base_length_m = 0.11
        self.max_wheel_speed_radps = 0.2 / 0.016
        self.max_angular_speed_radps = 2.0 * (0.016 / 0.11) * (0.2 / 0.016)


def dxi_to_dxu(dxi, theta_rad, params):
    """The thesis's dxi_to_dxu at heading `theta_rad` with `params`' vel_gain and ang_gain.

    v = k_v (c dx + s dy), w = k_w atan2(-s dx + c dy, v) / (pi/2): the turn uses the already
    scaled v, as the thesis does.
    """
    dx = float(dxi[0])
    dy = float(dxi[1])
    c = math.cos(theta_rad)
    s = math.sin(theta_rad)
    v = params.vel_gain * (c * dx + s * dy)
    w = params.ang_gain * math.atan2(-s * dx + c * dy, v) / HALF_PI
    return (v, w)


class ActuatorLimits:
    """The thesis's actuator_limit: clip v and w, then shrink |v| (keeping w) until every wheel
    is within its speed limit, because turning matters more than speed for where the robot
    ends up. NaN or infinity in, (0, 0) out."""

    __slots__ = ("limits",)

    def __init__(self, limits=None):
        self.limits = limits if limits is not None else RobotLimits()

    def apply(self, command):
        v = float(command[0])
        w = float(command[1])
        if not (math.isfinite(v) and math.isfinite(w)):
            return (0.0, 0.0)
        limits = self.limits
        v_max = limits.max_linear_speed_mps
        w_max = limits.max_angular_speed_radps
        v = -v_max if v < -v_max else (v_max if v > v_max else v)
        w = -w_max if w < -w_max else (w_max if w > w_max else w)
        r = limits.wheel_radius_m
        turn_share = limits.base_length_m / (2.0 * r) * abs(w)
        if abs(v) / r + turn_share > limits.max_wheel_speed_radps:
            # A hair inside the limit: exactly at it, the world's own uni->diff arithmetic can
            # land one ulp over and count an actuator warning.
            v_allowed = max(0.0, (limits.max_wheel_speed_radps - turn_share) * r * (1.0 - 1e-9))
            v = math.copysign(v_allowed, v)
        return (v, w)


class SingleIntegratorToUnicycle:
    """The Robotarium's create_si_to_uni_dynamics: v = k_v (forward . dxi),
    w = w_lim atan2(left . dxi, forward . dxi) / (pi/2), so a 90-degree heading error turns at w_lim."""

    __slots__ = ("linear_gain", "angular_limit_radps")

    def __init__(self, linear_gain=1.0, angular_limit_radps=math.pi):
        if not (linear_gain > 0.0 and math.isfinite(linear_gain)):
            raise ValueError(f"linear_gain must be positive, got {linear_gain!r}")
        if not (angular_limit_radps >= 0.0 and math.isfinite(angular_limit_radps)):
            raise ValueError(f"angular_limit_radps must be >= 0, got {angular_limit_radps!r}")
        self.linear_gain = linear_gain
        self.angular_limit_radps = angular_limit_radps

    def map(self, velocity_mps, theta_rad):
        """(v, w) for the world-frame velocity `velocity_mps` at heading `theta_rad`."""
        vx = float(velocity_mps[0])
        vy = float(velocity_mps[1])
        c = math.cos(theta_rad)
        s = math.sin(theta_rad)
        along = c * vx + s * vy
        across = -s * vx + c * vy
        return (self.linear_gain * along, self.angular_limit_radps * math.atan2(across, along) / HALF_PI)
