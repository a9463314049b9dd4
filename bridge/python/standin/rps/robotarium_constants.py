"""The official V2.0.0 Robotarium's class constants (rps/robotarium_abc.py), written once for the
two `Robotarium` classes that carry them: check-submission's stand-in (this package) and DREAM's
rps for unmodified scripts (python/rps_dream/rps, whose path reaches this folder)."""

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
    ENCODER_COUNTS_PER_REVOLUTION = 28
    MOTOR_GEAR_RATIO = 100.37
    MAX_WHEEL_VELOCITY = MAX_LINEAR_VELOCITY / WHEEL_RADIUS
    MAX_ANGULAR_VELOCITY = 2.0 * (WHEEL_RADIUS / ROBOT_DIAMETER) * (MAX_LINEAR_VELOCITY / WHEEL_RADIUS)
