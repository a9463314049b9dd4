"""Stand-in for rps.utilities.sensors: the official distance sensor models (rps/sensor_models.py,
which the Robotarium's step uses too)."""

import numpy as np  # noqa: F401  (the official module has it: `import *` scripts use it)

from rps.sensor_models import simulate_distance_sensors, simulate_distance_sensors_without_robots  # noqa: F401
