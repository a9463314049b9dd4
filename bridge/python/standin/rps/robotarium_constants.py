"""The official V2.0.0 Robotarium's class constants (rps/robotarium_abc.py), written once for the
two `Robotarium` classes that carry them: check-submission's stand-in (this package) and DREAM's
rps for unmodified scripts (python/rps_dream/rps, whose path reaches this folder)."""

import math

import numpy as np


class RobotariumConstants:
    """What scripts read off `Robotarium` (r.TIME_STEP, r.BOUNDARIES, ...), as the official class has them."""

    TIME_STEP = 0.033
    MAX_LINEAR_VELOCITY = 0.2
    ROBOT_DIAMETER = 0.11
    WHEEL_RADIUS = 0.016
    BASE_LENGTH = 0.11
    COLLISION_DIAMETER = 0.135
    COLLISION_OFFSET = 0.025
    BOUNDARIES = np.array([-1.6, 1.6, -1.0, 1.0])
    CENTER_OFFSET = 0.01
    # The simulated sensors (rps/sensor_models.py).
    DISTANCE_SENSOR_ERROR = 0.03
    DISTANCE_SENSOR_DROPOUT_PROB = 0.035
    DISTANCE_SENSOR_OUTLIER_PROB = 0.014
    DISTANCE_SENSOR_RANGE = 1.2
    # Each of the 7 distance sensors' body-frame x, y (m) and heading (rad).
    DISTANCE_SENSORS_ORIENTATION = np.array([
        [-0.04, 0.0, 0.04, 0.05, 0.04, 0.0, -0.04],
        [0.04, 0.06, 0.05, 0.0, -0.05, -0.06, -0.04],
        [math.pi, math.pi / 2, math.pi / 4, 0.0, -math.pi / 4, -math.pi / 2, -math.pi],
    ])
    ENCODER_COUNTS_PER_REVOLUTION = 28
    MOTOR_GEAR_RATIO = 100.37
    IMU_ORIENTATION = np.array([0.0594 - 0.00319, 0.0344628 - 0.0475, 0.0])
    ENCODER_NOISE_STD = 0.25
    ACCELEROMETER_NOISE_STDS = np.array([0.012929, 0.012127, 0.052979])
    GYRO_NOISE_STDS = np.array([0.001663, 0.001216, 0.002372])
    MAGNETOMETER_NOISE_STDS = np.array([3.275843, 2.365798, 5.232685])
    MAGNETOMETER_Z_AVG = -39.8594
    MAGNETOMETER_XY_AVG = 6.0712
    ORIENTATION_NOISE_STD = 0.310830
    MAX_WHEEL_VELOCITY = MAX_LINEAR_VELOCITY / WHEEL_RADIUS
    MAX_ANGULAR_VELOCITY = 2.0 * (WHEEL_RADIUS / ROBOT_DIAMETER) * (MAX_LINEAR_VELOCITY / WHEEL_RADIUS)
