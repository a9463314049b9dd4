"""The official V2.0.0 simulator's sensor models (rps/robotarium.py's simulate_* methods and
rps/utilities/sensors.py), for the stand-in's Robotarium and DREAM's rps: wheel encoders,
accelerometer, gyro, magnetometer, heading and, with use_distance_sensors=True, the seven
distance sensors. The numbers are the official ones: the same formulas in the same order, and
the same draws from numpy's global stream (a seeded script's stream stays the official one).
"""

import numpy as np


def _ray_hits_segment(start, ray, segment_start, segment_end):
    """Where along `ray` (0..1) it crosses the segment, or None (parallel or missed)."""
    along = segment_end - segment_start
    cross = ray[0] * along[1] - ray[1] * along[0]
    if abs(cross) < 1e-10:
        return None
    gap = segment_start - start
    t = (gap[0] * along[1] - gap[1] * along[0]) / cross
    u = (gap[0] * ray[1] - gap[1] * ray[0]) / cross
    return t if 0 <= t <= 1 and 0 <= u <= 1 else None


def _nearest_hit(start, ray, obstacles, others, robot_diameter, sensor_range):
    """The distance to the nearest obstacle segment or other robot (a disc) along the ray."""
    nearest = sensor_range
    if obstacles is not None and obstacles.size > 0:
        for k in range(obstacles.shape[0]):
            t = _ray_hits_segment(start, ray, obstacles[k, 0, :], obstacles[k, 1, :])
            if t is not None:
                nearest = min(nearest, np.linalg.norm(start + t * ray - start))
    if others is None:
        return nearest
    length = np.linalg.norm(ray)
    unit = ray / length
    for centre in others:
        along = np.dot(centre - start, unit)
        if 0 <= along <= length:
            off = np.linalg.norm(start + along * unit - centre)
            if off <= robot_diameter / 2:
                distance = along - np.sqrt((robot_diameter / 2) ** 2 - off ** 2)
                if distance >= 0:
                    nearest = min(nearest, distance)
    return nearest


def _noisy_reading(nearest, sensor_range, error, dropout, outlier):
    """-1 for nothing in range or a dropout; else an outlier or the distance with its noise."""
    if nearest >= sensor_range:
        return -1
    if np.random.rand() < dropout:
        return -1
    if np.random.rand() < outlier:
        return np.random.uniform(0, sensor_range)
    noise = error * nearest * np.random.randn()
    return np.clip(nearest + noise, 0, sensor_range)


def _sensor_mount(pose, mount):
    """Where a sensor sits (world frame) and the unit vector it looks along."""
    rotation = np.array([[np.cos(pose[2]), -np.sin(pose[2])], [np.sin(pose[2]), np.cos(pose[2])]])
    start = rotation @ mount[:2] + pose[:2]
    return start, np.array([np.cos(pose[2] + mount[2]), np.sin(pose[2] + mount[2])])


def simulate_distance_sensors(poses, obstacles, distance_sensors_orientation, robot_diameter,
                              robot_center_offset, distance_sensor_range, distance_sensor_error,
                              distance_sensor_dropout_prob, distance_sensor_outlier_prob):
    """rps.utilities.sensors.simulate_distance_sensors: 7 x N readings (m, -1 for none); the
    other robots are discs of robot_diameter around their centres (moved robot_center_offset forward)."""
    centred = poses.copy()
    centred[:2, :] += robot_center_offset * np.array([np.cos(poses[2, :]), np.sin(poses[2, :])])
    return _readings(centred, obstacles, distance_sensors_orientation, robot_diameter,
                     distance_sensor_range, (distance_sensor_error, distance_sensor_dropout_prob,
                                             distance_sensor_outlier_prob), True)


def simulate_distance_sensors_without_robots(poses, obstacles, distance_sensors_orientation, distance_sensor_range,
                                             distance_sensor_error, distance_sensor_dropout_prob,
                                             distance_sensor_outlier_prob):
    """rps.utilities.sensors.simulate_distance_sensors_without_robots: the obstacles alone."""
    return _readings(poses, obstacles, distance_sensors_orientation, 0.0, distance_sensor_range,
                     (distance_sensor_error, distance_sensor_dropout_prob, distance_sensor_outlier_prob), False)


def _readings(poses, obstacles, mounts, robot_diameter, sensor_range, noise, with_robots):
    n = poses.shape[1]
    distances = np.zeros((mounts.shape[1], n))
    for i in range(n):
        others = [poses[:2, m] for m in range(n) if m != i] if with_robots else None
        for j in range(mounts.shape[1]):
            start, direction = _sensor_mount(poses[:, i], mounts[:, j])
            ray = (start + sensor_range * direction) - start
            nearest = _nearest_hit(start, ray, obstacles, others, robot_diameter, sensor_range)
            distances[j, i] = _noisy_reading(nearest, sensor_range, *noise)
    return distances


class SensorModels:
    """The readings of N robots, updated by every step as the official step updates them.

    Every step draws its noise from numpy's global stream as the official step does (the distance
    sensors' first, then one draw of 12 N normals, which is the official randn(2, N), three
    randn(3, N) and randn(N) in a row: the legacy stream gives the same numbers however the calls
    split them), but the encoders, accelerometer, gyro, magnetometer and heading are worked out only
    when a getter asks: most scripts read none of them, and the official models cost a script's
    step ~0.1 ms. The readings are the official ones bit for bit (tests/python/test_standin_sensors.py)."""

    # Steps whose encoder counts wait to be added (bounded: folded in when this many wait).
    MAX_PENDING_STEPS = 512

    def __init__(self, constants, n, use_distance_sensors, obstacles):
        self.c = constants
        self.n = n
        self.distance_sensors = use_distance_sensors
        self.obstacles = obstacles
        self.distances = np.full((7, n), np.nan)  # NaN until the first step, as the official
        self.endpoints = np.full((2, 7, n), np.nan)
        self._encoders = np.zeros((2, n))
        self._pending_velocities = []  # per step not yet counted: (2 x N saturated velocities, 2 x N noise)
        self._pending_noise = []
        self._last = None  # (poses or a function giving them, velocities, noise) of the last step
        self._readings = {"accelerations": np.zeros((3, n)), "orientations": np.zeros(n),
                          "magnetic_fields": np.zeros((3, n)), "gyros": np.zeros((3, n))}

    def after_step(self, poses, velocities):
        """The readings after a step that drove `velocities` (saturated) and ended at `poses`, which
        may be a function giving them: it is called only when a reading needs the poses."""
        c, n = self.c, self.n
        if self.distance_sensors:
            poses = poses() if callable(poses) else poses
            self.distances = simulate_distance_sensors(
                poses, self.obstacles, c.DISTANCE_SENSORS_ORIENTATION, c.ROBOT_DIAMETER, c.CENTER_OFFSET,
                c.DISTANCE_SENSOR_RANGE, c.DISTANCE_SENSOR_ERROR, c.DISTANCE_SENSOR_DROPOUT_PROB,
                c.DISTANCE_SENSOR_OUTLIER_PROB)
            self.endpoints = self._endpoints(poses)
        noise = np.random.randn(12 * n)
        velocities = np.array(velocities, dtype=float)  # the caller's array changes with the next command
        self._pending_velocities.append(velocities)
        self._pending_noise.append(noise[:2 * n].reshape(2, n))
        if len(self._pending_velocities) >= self.MAX_PENDING_STEPS:
            self._count_encoders()
        self._last = (poses, velocities, noise[2 * n:])
        self._readings = None

    @property
    def encoders(self):
        self._count_encoders()
        return self._encoders

    @property
    def accelerations(self):
        return self._imu()["accelerations"]

    @property
    def gyros(self):
        return self._imu()["gyros"]

    @property
    def magnetic_fields(self):
        return self._imu()["magnetic_fields"]

    @property
    def orientations(self):
        return self._imu()["orientations"]

    def _endpoints(self, poses):
        ends = np.full((2, 7, self.n), np.nan)
        for i in range(self.n):
            for j in range(7):
                if self.distances[j, i] >= 0:
                    start, direction = _sensor_mount(poses[:, i], self.c.DISTANCE_SENSORS_ORIENTATION[:, j])
                    ends[:, j, i] = start + self.distances[j, i] * direction
        return ends

    def _count_encoders(self):
        """Adds the counts of the steps not yet counted, each rounded as the official rounds it."""
        if not self._pending_velocities:
            return
        c = self.c
        velocities = np.stack(self._pending_velocities)  # steps x 2 x N
        noise = np.stack(self._pending_noise)
        self._pending_velocities, self._pending_noise = [], []
        r, l = c.WHEEL_RADIUS, c.BASE_LENGTH
        wheels = np.stack([(1 / (2 * r)) * (2 * velocities[:, 0, :] - l * velocities[:, 1, :]),
                           (1 / (2 * r)) * (2 * velocities[:, 0, :] + l * velocities[:, 1, :])], axis=1)
        delta = wheels * c.TIME_STEP * c.ENCODER_COUNTS_PER_REVOLUTION * c.MOTOR_GEAR_RATIO / (2 * np.pi)
        step_noise_std = c.ENCODER_NOISE_STD * np.sqrt(np.maximum(np.abs(delta), 1.0))
        delta += step_noise_std * noise
        # Whole counts: their sum is exact in any order, so this is the official step-by-step sum.
        self._encoders += np.sum(np.round(delta), axis=0)

    def _imu(self):
        """Accelerometer, gyro, magnetometer, heading after the last step. The official step keeps
        the previous velocities only after it saturated the new ones, so its accelerations are
        always zero; centripetal and gravity remain, as there."""
        if self._readings is not None:
            return self._readings
        c, n = self.c, self.n
        poses, velocities, noise = self._last
        poses = poses() if callable(poses) else poses
        self._last = (poses, velocities, noise)
        accelerometer, gyro, magnetometer = (noise[k * 3 * n:(k + 1) * 3 * n].reshape(3, n) for k in range(3))
        linear = (velocities[0, :] - velocities[0, :]) / c.TIME_STEP
        angular = (velocities[1, :] - velocities[1, :]) / c.TIME_STEP
        omega = velocities[1, :]
        zeros = np.zeros(n)
        imu = (np.vstack([linear, zeros, zeros])
               + np.vstack([-angular * c.IMU_ORIENTATION[1], angular * c.IMU_ORIENTATION[0], zeros])
               + np.vstack([-np.square(omega) * c.IMU_ORIENTATION[0], -np.square(omega) * c.IMU_ORIENTATION[1], zeros])
               + np.vstack([zeros, zeros, -9.81 * np.ones(n)]))
        theta = poses[2, :]
        magnetic = np.vstack([c.MAGNETOMETER_XY_AVG * np.cos(theta), -c.MAGNETOMETER_XY_AVG * np.sin(theta),
                              c.MAGNETOMETER_Z_AVG * np.ones(n)])
        degrees = poses[2, :] * (180.0 / np.pi)
        self._readings = {
            "accelerations": imu + c.ACCELEROMETER_NOISE_STDS.reshape(3, 1) * accelerometer,
            "gyros": np.vstack([zeros, zeros, omega]) + c.GYRO_NOISE_STDS.reshape(3, 1) * gyro,
            "magnetic_fields": magnetic + c.MAGNETOMETER_NOISE_STDS.reshape(3, 1) * magnetometer,
            "orientations": np.mod(degrees + c.ORIENTATION_NOISE_STD * noise[9 * n:], 360.0)}
        return self._readings
