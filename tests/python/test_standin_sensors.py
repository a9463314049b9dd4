#!/usr/bin/python3
"""The stand-in's sensor models (bridge/python/standin/rps/sensor_models.py), which DREAM's rps gives
unmodified scripts: the distance sensors' geometry with the noise off (walls, other robots, nothing in
range, dropouts), the Robotarium getters' shapes and types, and, with ROBOTARIUM_PYTHON_SIMULATOR naming
a checkout (and matplotlib, which the official package imports), every reading against the official
simulator's on the same seeded steps, exactly.

Exit code 77 (skipped) when numpy is missing.
"""

import os
import random
import sys
import unittest

from unit_setup import SOURCE_DIR, require_numpy

require_numpy()
import numpy as np  # noqa: E402

STANDIN = os.path.join(SOURCE_DIR, "bridge", "python", "standin")

MOUNTS = np.array([[-0.04, 0.0, 0.04, 0.05, 0.04, 0.0, -0.04], [0.04, 0.06, 0.05, 0.0, -0.05, -0.06, -0.04],
                   [np.pi, np.pi / 2, np.pi / 4, 0.0, -np.pi / 4, -np.pi / 2, -np.pi]])
FRONT = 3  # the sensor looking straight ahead, 0.05 m in front of the axle
OFFSET, DIAMETER, RANGE = 0.01, 0.11, 1.2


def standin_modules():
    """The stand-in's rps, imported fresh (another test may have loaded the official one)."""
    for name in [name for name in sys.modules if name == "rps" or name.startswith("rps.")]:
        del sys.modules[name]
    sys.path.insert(0, STANDIN)
    try:
        from rps import robotarium, sensor_models
    finally:
        sys.path.remove(STANDIN)
    return robotarium, sensor_models


class DistanceGeometry(unittest.TestCase):
    def setUp(self):
        _, self.models = standin_modules()

    def read(self, poses, obstacles, dropout=0.0):
        return self.models.simulate_distance_sensors(poses, obstacles, MOUNTS, DIAMETER, OFFSET, RANGE, 0.0, dropout,
                                                     0.0)

    def test_a_wall_ahead_is_measured_from_the_sensor(self):
        wall = np.array([[[1.0, -1.0], [1.0, 1.0]]])
        reading = self.read(np.array([[0.0], [0.0], [0.0]]), wall)
        self.assertAlmostEqual(reading[FRONT, 0], 1.0 - OFFSET - 0.05, places=12)
        self.assertEqual(reading[0, 0], -1)  # the one looking back sees nothing in range

    def test_another_robot_is_a_disc_around_its_moved_centre(self):
        poses = np.array([[0.0, 0.5], [0.0, 0.0], [0.0, 0.0]])
        reading = self.read(poses, None)
        self.assertAlmostEqual(reading[FRONT, 0], (0.5 + OFFSET) - (OFFSET + 0.05) - DIAMETER / 2, places=12)

    def test_nothing_in_range_and_a_dropout_read_minus_one(self):
        far = np.array([[[1.5, -1.0], [1.5, 1.0]]])  # 1.44 m from the front sensor: out of range
        self.assertTrue(np.all(self.read(np.array([[0.0], [0.0], [0.0]]), far) == -1))
        near = np.array([[[0.5, -1.0], [0.5, 1.0]]])
        self.assertEqual(self.read(np.array([[0.0], [0.0], [0.0]]), near, dropout=1.0)[FRONT, 0], -1)


class RobotariumGetters(unittest.TestCase):
    def test_the_readings_after_steps(self):
        robotarium, _ = standin_modules()
        random.seed(3)
        np.random.seed(3)
        r = robotarium.Robotarium(number_of_robots=2, initial_conditions=np.array([[0.0, 0.5], [0.0, 0.0], [0.0, 0.0]]),
                                  skip_initialization=True, use_distance_sensors=True,
                                  obstacles=np.array([[[1.0, -1.0], [1.0, 1.0]]]))
        self.assertTrue(np.all(np.isnan(r.get_distances())))  # NaN until the first step, as the official
        for _ in range(30):
            r.get_poses()
            r.set_velocities(np.arange(2), np.array([[0.1, 0.1], [0.0, 0.5]]))
            r.step()
        self.assertEqual(r.get_encoders().dtype, np.int32)
        # 30 steps at 0.1 m/s straight: 6.25 rad/s per wheel, 6.25 * 0.033 * 28 * 100.37 / (2 pi) = 92.26 counts
        # a step, noise 0.25 sqrt(92) = 2.4 counts a step: 30 steps within 60 counts (4.5 sigma).
        self.assertTrue(np.all(np.abs(r.get_encoders()[:, 0] - 30 * 92.26) < 60), r.get_encoders())
        self.assertEqual(r.get_distance_endpoints().shape, (2, 7, 2))
        self.assertEqual(r.get_accelerations().shape, (3, 2))
        self.assertTrue(np.all(np.abs(r.get_accelerations()[2] + 9.81) < 0.5))
        self.assertTrue(np.all((r.get_orientations() >= 0) & (r.get_orientations() < 360)))
        with self.assertRaisesRegex(AssertionError, "M x 2 x 2"):
            robotarium.Robotarium(number_of_robots=1, initial_conditions=np.zeros((3, 1)), skip_initialization=True,
                                  obstacles=np.zeros((2, 3)))


class AgainstTheOfficial(unittest.TestCase):
    def both_sides(self, drive):
        """drive(rps.robotarium) on the official simulator and on the stand-in: {side: its result}."""
        simulator = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
        if not os.path.isfile(os.path.join(simulator, "rps", "robotarium.py")):
            self.skipTest("ROBOTARIUM_PYTHON_SIMULATOR names no checkout of the official simulator")
        try:
            import matplotlib
            matplotlib.use("Agg")
        except ImportError:
            self.skipTest("the official simulator needs matplotlib")
        readings = {}
        for side in ("official", "standin"):
            for name in [name for name in sys.modules if name == "rps" or name.startswith("rps.")]:
                del sys.modules[name]
            sys.path.insert(0, simulator if side == "official" else STANDIN)
            try:
                from rps import robotarium
            finally:
                sys.path.pop(0)
            readings[side] = drive(robotarium)
        return readings

    def test_every_reading_is_the_official_one(self):
        readings = self.both_sides(self.drive)
        for key, official in readings["official"].items():
            np.testing.assert_array_equal(readings["standin"][key], official, err_msg=key)

    def test_readings_asked_for_late_are_the_official_ones(self):
        """The stand-in works the readings out only when a getter asks (its encoders add up the steps
        not yet counted, at most SensorModels.MAX_PENDING_STEPS at a time): read once after 700 steps,
        they are the official ones, and numpy's stream is where the official one left it."""
        def drive(robotarium):
            random.seed(8)
            np.random.seed(8)
            r = robotarium.Robotarium(number_of_robots=3, show_figure=False, sim_in_real_time=False,
                                      initial_conditions=np.array([[-0.5, 0.0, 0.5], [0.0, 0.3, -0.3],
                                                                   [0.0, 1.0, -2.0]]), skip_initialization=True)
            for step in range(700):
                r.get_poses()
                r.set_velocities(np.arange(3), np.vstack([0.1 * np.cos(step / 50 + np.arange(3)),
                                                          np.sin(step / 9 + np.arange(3))]))
                r.step()
            seen = {name: getattr(r, "get_" + name)() for name in
                    ("encoders", "accelerations", "gyros", "magnetic_fields", "orientations")}
            seen["next_draw"] = np.random.rand(4)
            return seen

        readings = self.both_sides(drive)
        self.assertGreater(np.max(np.abs(readings["official"]["encoders"])), 1000)
        for key, official in readings["official"].items():
            np.testing.assert_array_equal(readings["standin"][key], official, err_msg=key)

    @staticmethod
    def drive(robotarium):
        random.seed(5)
        np.random.seed(5)
        walls = np.array([[[-1.6, -1.0], [1.6, -1.0]], [[-1.6, 1.0], [1.6, 1.0]], [[0.3, -0.5], [0.3, 0.5]]])
        r = robotarium.Robotarium(number_of_robots=4, show_figure=False, sim_in_real_time=False,
                                  initial_conditions=np.array([[-0.8, -0.4, 0.0, 0.6], [0.0, 0.3, -0.3, 0.2],
                                                               [0.0, 1.0, -2.0, 3.0]]),
                                  skip_initialization=True, use_distance_sensors=True, obstacles=walls)
        seen = {}
        for step in range(60):
            r.get_poses()
            r.set_velocities(np.arange(4), np.vstack([np.full(4, 0.15), np.sin(step / 9 + np.arange(4))]))
            r.step()
            for name in ("distances", "distance_endpoints", "encoders", "accelerations", "gyros", "magnetic_fields",
                         "orientations"):
                seen.setdefault(name, []).append(getattr(r, "get_" + name)())
        return {name: np.array(values) for name, values in seen.items()}


if __name__ == "__main__":
    unittest.main()
