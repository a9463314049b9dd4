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
Differences from the official simulator, on purpose:
  - No figure, no real-time throttle, no sensors (distances, IMU, encoders).
  - Start-up: the official simulator drives the robots from their chargers to
    the initial conditions and stops within 0.05 m / 0.2 rad of them. The
    stand-in puts each robot at its initial condition moved by a fixed,
    deterministic offset of that order (up to 0.03 m and 0.1 rad), so scripts
    meet an imperfect start as on the lab; start-up steps are not counted.
    skip_initialization=True starts exactly at the initial conditions, as the
    official simulator does with that flag.
"""

import math

import numpy as np


class Robotarium:
    """Robotarium(number_of_robots=N, initial_conditions=3xN array, ...)."""

    TIME_STEP = 0.033
    MAX_LINEAR_VELOCITY = 0.2
    ROBOT_DIAMETER = 0.11
    WHEEL_RADIUS = 0.016
    BASE_LENGTH = 0.11
    COLLISION_DIAMETER = 0.135
    COLLISION_OFFSET = 0.025
    BOUNDARIES = np.array([-1.6, 1.6, -1.0, 1.0])
    MAX_WHEEL_VELOCITY = MAX_LINEAR_VELOCITY / WHEEL_RADIUS
    MAX_ANGULAR_VELOCITY = 2.0 * (WHEEL_RADIUS / ROBOT_DIAMETER) * (MAX_LINEAR_VELOCITY / WHEEL_RADIUS)

    # V2.0.0 places robots on 22 charger slots before the start-up drive and
    # fails above 22 robots even with initial conditions; the stand-in says so.
    CHARGER_SLOTS = 22

    START_OFFSET_M = 0.03
    START_OFFSET_RAD = 0.1

    def __init__(self, number_of_robots=-1, show_figure=False, initial_conditions=np.array([]),
                 sim_in_real_time=True, skip_initialization=False, **unused_options):
        if not isinstance(number_of_robots, int) or isinstance(number_of_robots, bool):
            raise AssertionError("NumberOfRobots must be an integer. Received type %s." %
                                 type(number_of_robots).__name__)
        for name, value in (("ShowFigure", show_figure), ("SimInRealTime", sim_in_real_time),
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
        if initial_conditions.size == 0:
            raise NotImplementedError("the stand-in needs initial_conditions (3 x N)")
        if initial_conditions.shape != (3, n):
            raise AssertionError("initial_conditions must be 3 x %d, got %s" % (n, initial_conditions.shape))
        if not np.all(np.isfinite(initial_conditions)):
            raise AssertionError("initial_conditions must be finite")

        self._poses = np.array(initial_conditions, dtype=float)
        if not skip_initialization:
            self._poses = self._poses + self._start_offsets(n)
        self._velocities = np.zeros((2, n))
        self._iteration = 0
        self._errors = {}
        self._poses_read = False
        self._stepped = True
        print("Initializing %d robots to initial conditions..." % n)
        print("At initial conditions... Starting Experiment")

    @classmethod
    def _start_offsets(cls, n):
        """Deterministic offsets like the lab's start-up leaves them (within its 0.05 m / 0.2 rad)."""
        offsets = np.zeros((3, n))
        for i in range(n):
            angle = 2.399963 * i  # golden angle: directions spread evenly
            radius = cls.START_OFFSET_M * (0.5 + 0.5 * ((i * 7) % 5) / 4.0)
            offsets[0, i] = radius * math.cos(angle)
            offsets[1, i] = radius * math.sin(angle)
            offsets[2, i] = cls.START_OFFSET_RAD * (1.0 if i % 2 == 0 else -1.0) * (0.4 + 0.6 * ((i * 3) % 4) / 3.0)
        return offsets

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
        n = self.number_of_robots
        for i in range(n - 1):
            gaps = np.linalg.norm(centres[:, i + 1:] - centres[:, i:i + 1], axis=0)
            close = int(np.count_nonzero(gaps <= self.COLLISION_DIAMETER))
            if close:
                self._count("robots_too_close", close)
        if np.any(np.abs(self._wheel_speeds(self._velocities)) > self.MAX_WHEEL_VELOCITY):
            self._count("exceeded_actuator_limits")

    def step(self):
        if self._stepped:
            raise AssertionError("Make sure you call get_poses before calling step()!")
        self._stepped = True
        self._poses_read = False
        self._validate()
        self._iteration += 1
        self._velocities = self._saturate(self._velocities)
        i = np.arange(self.number_of_robots)
        distance = self.TIME_STEP * self._velocities[0, i]
        self._poses[0, i] += distance * np.cos(self._poses[2, i])
        self._poses[1, i] += distance * np.sin(self._poses[2, i])
        self._poses[2, i] += self.TIME_STEP * self._velocities[1, i]
        self._poses[2, i] = np.arctan2(np.sin(self._poses[2, i]), np.cos(self._poses[2, i]))

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
