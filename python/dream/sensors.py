"""Sensors: what a robot learns from the world each time they run (agents/src/sensors.cc).

Each sensor owns its noise stream, numpy Generator(PCG64(seed)) with the seed mixed from the
run seed, the robot id and the sensor's index, so runs repeat whatever the process layout;
a sensor whose noise_std is 0 never draws. Hot loops use plain floats from the snapshot's
pose_rows: for a few robots that is faster than numpy.
"""

import math

import numpy as np

from .robot import MovementReading, NeighbourDetection, ObstacleReading, ObstacleRectangle, OdometryReading, number_text

FULL_CIRCLE_SLACK_RAD = 1e-4  # 2 pi as people write it (6.2832, rounded up) is a full circle too


def wrap_angle(angle_rad):
    """`angle_rad` in [-pi, pi], as atan2(sin, cos)."""
    return math.atan2(math.sin(angle_rad), math.cos(angle_rad))


def _check_non_negative(name, value):
    if not (math.isfinite(value) and value >= 0.0):
        raise ValueError(f"{name} must be >= 0, got {number_text(value)}")


def _check_positive(name, value):
    if not (math.isfinite(value) and value > 0.0):
        raise ValueError(f"{name} must be > 0, got {number_text(value)}")


def _noise_generator(noise_std, seed):
    return np.random.Generator(np.random.PCG64(seed)) if noise_std > 0.0 else None


class OdometrySensor:
    """The robot's own pose plus gaussian noise on x, y and theta (theta wrapped to [-pi, pi])."""

    __slots__ = ("noise_std", "_noise")

    def __init__(self, noise_std=0.0, seed=0):
        _check_non_negative("noise_std", noise_std)
        self.noise_std = noise_std
        self._noise = _noise_generator(noise_std, seed)

    def sense(self, world, robot):
        x, y, theta = world.pose_rows[robot.id]
        if self._noise is not None:
            nx, ny, ntheta = self._noise.normal(0.0, self.noise_std, 3).tolist()
            x += nx
            y += ny
            theta += ntheta
        robot.on_odometry(OdometryReading(world.step, np.array((x, y, wrap_angle(theta)))))


class MovementSensor:
    """Every other robot within range_m whose bearing is within the field of view (centred
    direction_rad off the robot's heading), in robot id order: distance, world-frame bearing
    and the world-frame velocity of its point velocity_point_ahead_m ahead, from the (v, w) it
    drove. Noise is added to distance, bearing, vx and vy, drawn in that order."""

    __slots__ = ("range_m", "direction_rad", "field_of_view_rad", "noise_std", "velocity_point_ahead_m",
                 "_half_fov", "_noise")

    def __init__(self, range_m=1.0, direction_rad=0.0, field_of_view_rad=2.0 * math.pi, noise_std=0.0,
                 velocity_point_ahead_m=0.05, seed=0):
        _check_positive("range_m", range_m)
        if not math.isfinite(direction_rad):
            raise ValueError("direction_rad must be finite")
        if not (field_of_view_rad > 0.0 and field_of_view_rad <= 2.0 * math.pi + FULL_CIRCLE_SLACK_RAD):
            raise ValueError(f"field_of_view_rad must be in (0, 2 pi = 6.2832], got {number_text(field_of_view_rad)}")
        _check_non_negative("noise_std", noise_std)
        _check_non_negative("velocity_point_ahead_m", velocity_point_ahead_m)
        self.range_m = range_m
        self.direction_rad = direction_rad
        self.field_of_view_rad = field_of_view_rad
        self.noise_std = noise_std
        self.velocity_point_ahead_m = velocity_point_ahead_m
        self._half_fov = field_of_view_rad / 2.0
        self._noise = _noise_generator(noise_std, seed)

    def sense(self, world, robot):
        self_id = robot.id
        poses = world.pose_rows
        velocities = world.velocity_rows
        own_x, own_y, own_theta = poses[self_id]
        visible_half_angle = self._half_fov + 1e-12
        # |wrap_angle(.)| <= pi: a full circle sees every bearing, so skip the test.
        sees_all_around = visible_half_angle >= math.pi
        ahead = self.velocity_point_ahead_m
        noise = self._noise
        neighbours = []
        for i, (x, y, theta) in enumerate(poses):
            if i == self_id:
                continue
            dx = x - own_x
            dy = y - own_y
            distance = math.sqrt(dx * dx + dy * dy)
            if distance <= 0.0 or distance > self.range_m:
                continue
            bearing = math.atan2(dy, dx)
            if not sees_all_around and abs(wrap_angle(bearing - own_theta - self.direction_rad)) > visible_half_angle:
                continue
            v, w = velocities[i] if i < len(velocities) else (0.0, 0.0)
            c = math.cos(theta)
            s = math.sin(theta)
            vx = c * v - ahead * s * w
            vy = s * v + ahead * c * w
            if noise is not None:
                n_distance, n_bearing, n_vx, n_vy = noise.normal(0.0, self.noise_std, 4).tolist()
                distance += n_distance
                bearing = wrap_angle(bearing + n_bearing)
                vx += n_vx
                vy += n_vy
            else:
                bearing = wrap_angle(bearing)
            neighbours.append(NeighbourDetection(distance, bearing, np.array((vx, vy))))
        robot.on_movement(MovementReading(world.step, neighbours))


class ObstacleSensor:
    """The closest point of every obstacle within range_m, and its rectangle, both shifted by
    the same noise (x drawn before y)."""

    __slots__ = ("range_m", "noise_std", "_noise")

    def __init__(self, range_m=1.0, noise_std=0.0, seed=0):
        _check_positive("range_m", range_m)
        _check_non_negative("noise_std", noise_std)
        self.range_m = range_m
        self.noise_std = noise_std
        self._noise = _noise_generator(noise_std, seed)

    def sense(self, world, robot):
        own_x, own_y = world.pose_rows[robot.id][:2]
        closest_points = []
        rectangles = []
        for obstacle in world.obstacles:
            cx, cy = obstacle.center_m
            width, height = obstacle.size_m
            closest_x = min(max(own_x, cx - width / 2.0), cx + width / 2.0)
            closest_y = min(max(own_y, cy - height / 2.0), cy + height / 2.0)
            gap_x = closest_x - own_x
            gap_y = closest_y - own_y
            if math.sqrt(gap_x * gap_x + gap_y * gap_y) > self.range_m:
                continue
            if self._noise is not None:
                nx, ny = self._noise.normal(0.0, self.noise_std, 2).tolist()
                closest_x += nx
                closest_y += ny
                cx += nx
                cy += ny
            closest_points.append(np.array((closest_x, closest_y)))
            rectangles.append(ObstacleRectangle(np.array((cx, cy)), np.array((width, height))))
        robot.on_obstacles(ObstacleReading(world.step, closest_points, rectangles))
