"""Stand-in for rps.robotarium: the Robotarium V2 API with its step rules.

Semantics (V2.0.0, as DREAM's simulator reproduces them):
  - step() validates the poses *before* the step and the velocities as set:
    +1 boundary error per step with any robot strictly outside the arena, +1
    collision error per pair whose centres (moved 0.025 m forward) are <= 0.135 m
    apart, +1 actuator error per step where any wheel speed exceeds the limit;
    then saturates each wheel (uni->diff, clip, diff->uni), keeps the result as
    the held velocity and takes an Euler step with the heading wrapped by atan2.
  - get_poses() once per step(), step() once per get_poses().
  - debug() prints the same text as the official simulator.
  - Start-up: as the official simulator, the robots come off random charger slots
    (Python's `random`) and the start-up drive (rps/startup_drive.py) takes them onto
    the initial conditions with the unicycle barrier certificate; the experiment
    starts where it ended, within 0.05 m / 0.2 rad. Its steps count in debug()'s
    iterations but not as errors. skip_initialization=True starts exactly at the
    initial conditions (the placement is still drawn, as the official one draws it).
  - Sensors: every step updates the official sensor models (rps/sensor_models.py: encoders,
    accelerometer, gyro, magnetometer, heading, and the distance sensors with
    use_distance_sensors=True) with the official draws from numpy's global stream, so the
    getters give the official readings and a seeded script's numpy draws are the official ones
    (the readings but the distances are worked out when a getter asks).
Differences from the official simulator, on purpose:
  - No figure, no real-time throttle.
"""

import numpy as np

from rps import sensor_models, startup_drive
from rps.robotarium_constants import RobotariumConstants
from rps.utilities.barrier_certificates import create_uni_barrier_certificate


def _checked_obstacles(obstacles):
    """None, or M x 2 x 2 finite line segments (start, end) for the distance sensors."""
    if obstacles is None:
        return None
    array = np.asarray(obstacles, dtype=float)
    if array.ndim != 3 or array.shape[1:] != (2, 2) or array.shape[0] > 10000:
        raise AssertionError("obstacles must be an M x 2 x 2 array of segments (M <= 10000), got shape %s" %
                             (array.shape,))
    if not np.all(np.isfinite(array)):
        raise AssertionError("obstacles must be finite")
    return array


class Robotarium(RobotariumConstants):
    """Robotarium(number_of_robots=N, initial_conditions=3xN array, ...)."""


    # V2.0.0 places robots on 22 charger slots before the start-up drive and
    # fails above 22 robots even with initial conditions; the stand-in says so.
    CHARGER_SLOTS = 22

    def __init__(self, number_of_robots=-1, show_figure=False, initial_conditions=np.array([]),
                 sim_in_real_time=True, skip_initialization=False, use_distance_sensors=False, obstacles=None,
                 **unused_options):
        if not isinstance(number_of_robots, int) or isinstance(number_of_robots, bool):
            raise AssertionError("NumberOfRobots must be an integer. Received type %s." %
                                 type(number_of_robots).__name__)
        for name, value in (("ShowFigure", show_figure), ("SimInRealTime", sim_in_real_time),
                            ("UseDistanceSensors", use_distance_sensors),
                            ("SkipInitialization", skip_initialization)):
            if not isinstance(value, bool):
                raise AssertionError("%s must be a boolean. Received type %s." % (name, type(value).__name__))
        if not isinstance(initial_conditions, np.ndarray):
            raise AssertionError("InitialConditions must be a numpy ndarray. Received type %s." %
                                 type(initial_conditions).__name__)
        if not 0 <= number_of_robots <= 50:
            raise AssertionError("Number of robots must be >= 0 and <= 50")
        if number_of_robots > self.CHARGER_SLOTS:
            raise ValueError("Sample larger than population or is negative (the official V2.0.0 simulator "
                             "cannot start more than %d robots)" % self.CHARGER_SLOTS)
        n = number_of_robots
        self.number_of_robots = n
        # Drawn first, in the official order: the charger slots, then default initial conditions.
        chargers = startup_drive.charger_poses(n, self.BOUNDARIES[1] - self.BOUNDARIES[0] - self.ROBOT_DIAMETER,
                                               self.BOUNDARIES[3] - self.BOUNDARIES[2] - self.ROBOT_DIAMETER)
        if initial_conditions.size == 0:
            initial_conditions = startup_drive.random_poses(n, 0.5, startup_drive.RANDOM_POSE_WIDTH,
                                                            startup_drive.RANDOM_POSE_HEIGHT)
        if initial_conditions.shape != (3, n):
            raise AssertionError("initial_conditions must be 3 x %d, got %s" % (n, initial_conditions.shape))
        if not np.all(np.isfinite(initial_conditions)):
            raise AssertionError("initial_conditions must be finite")

        self.obstacles = _checked_obstacles(obstacles)
        self._sensors = sensor_models.SensorModels(self, n, use_distance_sensors, self.obstacles)
        self._pairs = np.triu_indices(n, k=1)  # every pair i < j, for the collision check
        self._poses = np.array(chargers, dtype=float).reshape(3, n)
        self._velocities = np.zeros((2, n))
        self._iteration = 0
        self._errors = {}
        self._poses_read = False
        self._stepped = True
        # True during the start-up drive: no errors are counted (run_submission.py watches it too).
        self.initializing = True
        if skip_initialization:
            self._poses = np.array(initial_conditions, dtype=float)
        else:
            print("Initializing %d robots to initial conditions..." % n)
            startup_drive.drive(self, np.array(initial_conditions, dtype=float), create_uni_barrier_certificate())
            print("At initial conditions... Starting Experiment")
        self.initializing = False

    def get_poses(self):
        if self._poses_read:
            raise AssertionError("Can only call get_poses() once per call of step()!")
        self._poses_read = True
        self._stepped = False
        return self._poses.copy()

    def set_velocities(self, ids, velocities):
        if velocities.shape[1] > self.number_of_robots:
            raise AssertionError("Column count of velocities (%d) must be <= number_of_robots (%d)" %
                                 (velocities.shape[1], self.number_of_robots))
        self._velocities[:, ids] = velocities

    def _wheel_speeds(self, dxu):
        r = self.WHEEL_RADIUS
        l = self.BASE_LENGTH
        return np.vstack([(1 / (2 * r)) * (2 * dxu[0, :] - l * dxu[1, :]),
                          (1 / (2 * r)) * (2 * dxu[0, :] + l * dxu[1, :])])

    def _saturate(self, dxu):
        wheels = self._wheel_speeds(dxu)
        over = np.abs(wheels) > self.MAX_WHEEL_VELOCITY
        wheels[over] = self.MAX_WHEEL_VELOCITY * np.sign(wheels[over])
        r = self.WHEEL_RADIUS
        l = self.BASE_LENGTH
        return np.vstack([(r / 2) * (wheels[0, :] + wheels[1, :]), (r / l) * (wheels[1, :] - wheels[0, :])])

    def _count(self, key, amount=1):
        self._errors[key] = self._errors.get(key, 0) + amount

    def _validate(self):
        p = self._poses
        b = self.BOUNDARIES
        if np.any((p[0] < b[0]) | (p[0] > b[1]) | (p[1] < b[2]) | (p[1] > b[3])):
            self._count("robots_outside_boundaries")
        centres = p[:2, :] + self.COLLISION_OFFSET * np.vstack([np.cos(p[2, :]), np.sin(p[2, :])])
        first, second = self._pairs
        gaps = np.linalg.norm(centres[:, second] - centres[:, first], axis=0)
        close = int(np.count_nonzero(gaps <= self.COLLISION_DIAMETER))
        if close:  # one error per pair too close, as the official counts them
            self._count("robots_too_close", close)
        if np.any(np.abs(self._wheel_speeds(self._velocities)) > self.MAX_WHEEL_VELOCITY):
            self._count("exceeded_actuator_limits")

    def step(self):
        if self._stepped:
            raise AssertionError("Make sure you call get_poses before calling step()!")
        self._stepped = True
        self._poses_read = False
        if not self.initializing:
            self._validate()
        self._iteration += 1
        self._velocities = self._saturate(self._velocities)
        self._poses = self._integrated(self._poses, self._velocities)
        self._sensors.after_step(self._poses, self._velocities)

    def _integrated(self, poses, velocities):
        """The poses after one Euler step at the (saturated) velocities, heading wrapped by atan2."""
        poses = poses.copy()
        i = np.arange(self.number_of_robots)
        distance = self.TIME_STEP * velocities[0, i]
        poses[0, i] += distance * np.cos(poses[2, i])
        poses[1, i] += distance * np.sin(poses[2, i])
        poses[2, i] += self.TIME_STEP * velocities[1, i]
        poses[2, i] = np.arctan2(np.sin(poses[2, i]), np.cos(poses[2, i]))
        return poses

    # The sensors' readings after the last step (rps/sensor_models.py), as the official getters give them.
    def get_distances(self):
        return self._sensors.distances.copy()

    def get_distance_endpoints(self):
        if not self._sensors.distance_sensors:
            raise AssertionError("get_distance_endpoints() needs Robotarium(use_distance_sensors=True)")
        return self._sensors.endpoints.copy()

    def get_accelerations(self):
        return self._sensors.accelerations.copy()

    def get_orientations(self):
        return self._sensors.orientations.copy()

    def get_magnetic_fields(self):
        return self._sensors.magnetic_fields.copy()

    def get_gyros(self):
        return self._sensors.gyros.copy()

    def get_encoders(self):
        return np.int32(self._sensors.encoders)  # counts since the start, the drive included, as the official

    def debug(self):
        seconds = self._iteration * self.TIME_STEP
        print("Your simulation took approximately %.2f real seconds to execute.\n" % seconds)
        too_close = self._errors.get("robots_too_close", 0)
        outside = self._errors.get("robots_outside_boundaries", 0)
        actuator = self._errors.get("exceeded_actuator_limits", 0)
        if too_close + outside == 0 and actuator == 0:
            print("No errors or warnings in your simulation!  Your script will run on the Robotarium!\n")
        elif too_close + outside == 0:
            print("No hard errors detected, your script will run on the Robotarium!\n")
            print("WARNING: %d out of %d (~%.0f%%) timesteps had velocity command(s) exceed actuator limits.\n"
                  "         A large percentage of exceeded actuator commands will cause noticeable\n"
                  "         differences between this simulation and the physical Robotarium." %
                  (actuator, self._iteration, 100 * actuator / max(self._iteration, 1)))
        else:
            print("Errors detected, your script will NOT run on the Robotarium!\n")
            print("Errors:")
            if too_close:
                print("\t Simulation had %d time steps where robots were too close (potential collision)." %
                      too_close)
            if outside:
                print("\t Simulation had %d time steps where robots were outside boundaries." % outside)
            print("\nPlease fix the noted errors in your simulation; otherwise, your experiment will be rejected.")
