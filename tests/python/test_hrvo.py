#!/usr/bin/python3
"""Tests of the Python HRVO (python/dream/hrvo.py) and the Python HRVO circle swap
(config/python/hrvo_circle.py):

- the port gives the C++ answers (HrvoExact, HrvoThesis), to 1e-12, on
  tests/data/hrvo_python_reference.json (500 situations made by make_hrvo_reference.py with the
  C++ code);
- HrvoParams' checks and the `hrvo:` config section read as C++ reads them;
- the circle robot's radio protocol (hop-by-hop highest states, bad payloads counted);
- the circle swap, built through ControllerSpec, finishes all three formations in the pure-Python
  world of hrvo_circle_world.py without collisions or boundary errors.

Exit code 77 (skipped) when numpy is missing.
"""

import json
import math
import os
import struct
import unittest

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_numpy

require_numpy()
import numpy as np  # noqa: E402
put_runtime_on_path()

from dream import OdometryReading, RadioMessage  # noqa: E402
from dream.hrvo import HrvoAvoidance, HrvoParams  # noqa: E402

import hrvo_circle_world  # noqa: E402

REFERENCE = os.path.join(SOURCE_DIR, "tests", "data", "hrvo_python_reference.json")


def avoidance_for(case):
    safety, max_speed, check_boundaries, horizon, keep_right, margin = case["params"]
    params = HrvoParams(safety_radius_m=safety, max_speed_mps=max_speed, check_boundaries=bool(check_boundaries),
                        boundary_horizon_s=horizon)
    return HrvoAvoidance(params, variant=case["variant"], keep_right_rad=keep_right, wall_margin_m=margin)


class MatchesTheCppHrvo(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(REFERENCE) as file:
            cls.cases = json.load(file)["cases"]

    def test_reference_covers_the_hard_paths(self):
        exact = [case for case in self.cases if case["variant"] == "exact"]
        self.assertGreaterEqual(len(exact), 300)
        self.assertGreaterEqual(len(self.cases) - len(exact), 100)
        self.assertGreaterEqual(sum(not case["safe"] for case in exact), 30)  # the boxed-in fallback
        self.assertGreaterEqual(sum(len(case["neighbours"]) >= 9 for case in exact), 30)

    def test_every_reference_case(self):
        for index, case in enumerate(self.cases):
            with self.subTest(case=index):
                hrvo = avoidance_for(case)
                velocity = hrvo.safe_velocity(case["position"], case["current"], case["preferred"], case["neighbours"])
                self.assertIsInstance(velocity, np.ndarray)
                np.testing.assert_allclose(velocity, case["expected"], rtol=0.0, atol=1e-12)
                self.assertEqual(hrvo.last_was_safe, case["safe"])
                if case["variant"] == "exact":
                    self.assertEqual(len(hrvo.last_cones), len(case["neighbours"]))

    def test_array_and_float_inputs_give_the_same_answer(self):
        case = next(c for c in self.cases if len(c["neighbours"]) >= 5 and not c["safe"])
        hrvo = avoidance_for(case)
        from_arrays = hrvo.safe_velocity(np.array(case["position"]), np.array(case["current"]),
                                         np.array(case["preferred"]), np.array(case["neighbours"]))
        from_floats = hrvo.solve(*case["position"], *case["current"], *case["preferred"],
                                 [tuple(row) for row in case["neighbours"]])
        np.testing.assert_array_equal(from_arrays, case["expected"])
        self.assertEqual(from_floats, tuple(case["expected"]))

    def test_non_finite_inputs_are_ignored_as_in_cpp(self):
        hrvo = HrvoAvoidance()
        velocity = hrvo.safe_velocity([0.0, 0.0], [math.nan, 0.0], [0.2, 0.0],
                                      [[0.5, 0.0, 0.0, 0.0], [math.inf, 0.0, 0.0, 0.0]])
        self.assertEqual(len(hrvo.last_cones), 1)  # the non-finite neighbour is skipped
        self.assertLess(velocity[1], 0.0)  # keeps right of the still neighbour ahead
        np.testing.assert_array_equal(hrvo.safe_velocity([0.0, 0.0], [0.0, 0.0], [math.nan, 1.0], []), [0.0, 0.0])


class ParamsAreCheckedAsInCpp(unittest.TestCase):
    def test_defaults_are_the_thesis_values(self):
        params = HrvoParams()
        self.assertEqual((params.safety_radius_m, params.max_speed_mps, params.check_boundaries,
                          params.boundary_horizon_s), (0.24, 0.2, True, 1.0))
        self.assertEqual((params.x_min_m, params.x_max_m, params.y_min_m, params.y_max_m), (-1.6, 1.6, -1.0, 1.0))

    def test_out_of_range_values_name_field_value_and_range(self):
        for fields, message in [({"safety_radius_m": 0.0}, "HrvoParams.safety_radius_m = 0 is outside (0, 10] m"),
                                ({"max_speed_mps": 11.0}, "HrvoParams.max_speed_mps = 11 is outside (0, 10] m/s"),
                                ({"x_max_m": -2.0}, "HrvoParams.x_max_m = -2 is outside (x_min_m, inf) m"),
                                ({"y_min_m": math.nan}, "HrvoParams.y_min_m = nan is outside finite values"),
                                ({"boundary_horizon_s": 0.0},
                                 "HrvoParams.boundary_horizon_s = 0 is outside (0, 100] s")]:
            with self.subTest(fields=fields):
                with self.assertRaises(ValueError) as raised:
                    HrvoAvoidance(HrvoParams(**fields))
                self.assertEqual(str(raised.exception), message)

    def test_tuning_is_checked(self):
        with self.assertRaisesRegex(ValueError, r"keep_right_rad = 1\.6 is outside \[0, pi/2\) rad"):
            HrvoAvoidance(keep_right_rad=1.6)
        with self.assertRaisesRegex(ValueError, r"wall_margin_m = 0\.6 is outside \[0, 0\.5\] m"):
            HrvoAvoidance(wall_margin_m=0.6)

    def test_config_section(self):
        params = HrvoParams.from_config({"variant": "exact", "safety_radius_m": 0.3, "check_boundaries": False,
                                         "boundary_horizon_s": 2})
        self.assertEqual((params.safety_radius_m, params.check_boundaries, params.boundary_horizon_s),
                         (0.3, False, 2.0))
        self.assertEqual(HrvoParams.from_config(None).safety_radius_m, 0.24)
        self.assertEqual(HrvoAvoidance.from_config({"variant": "thesis"}).variant, "thesis")
        self.assertEqual(HrvoAvoidance.from_config(None).variant, "exact")
        with self.assertRaisesRegex(ValueError, "unknown HRVO variant 'sampled'; allowed: exact, thesis"):
            HrvoAvoidance(variant="sampled")
        for section, message in [({"speed": 1}, "hrvo.speed: unknown key; allowed keys here: variant, "
                                                "safety_radius_m, check_boundaries, boundary_horizon_s"),
                                 ({"safety_radius": 0.3},
                                  "hrvo.safety_radius: unknown key (did you mean 'safety_radius_m'?); allowed"),
                                 ({"variant": "exat"},
                                  "hrvo.variant: unknown HRVO variant 'exat' (did you mean 'exact'?); allowed"),
                                 ({"variant": "fast"},
                                  "hrvo.variant: unknown HRVO variant 'fast'; allowed: exact, thesis"),
                                 ({"safety_radius_m": "big"}, "hrvo.safety_radius_m: expected a number"),
                                 ({"check_boundaries": 1}, "hrvo.check_boundaries: expected true or false"),
                                 ({"safety_radius_m": -1}, "hrvo: HrvoParams.safety_radius_m = -1 is outside")]:
            with self.subTest(section=section):
                with self.assertRaises(ValueError) as raised:
                    HrvoParams.from_config(section)
                self.assertTrue(str(raised.exception).startswith(message), str(raised.exception))


def progress_payload(states):
    return struct.pack(f"<{len(states) + 1}i", len(states), *states)


class CircleRobotRadio(unittest.TestCase):
    def setUp(self):
        self.agents = hrvo_circle_world.circle_agents(4)
        self.robot = self.agents[0].robot

    def test_goals_are_the_circle_point_its_opposite_and_back(self):
        robot = self.agents[1].robot
        np.testing.assert_allclose(robot.goals, [[0.0, 0.85], [0.0, -0.85], [0.0, 0.85]], atol=1e-15)

    def test_news_travels_as_the_highest_state_of_everybody(self):
        payload = self.robot.on_radio([RadioMessage(1, 5, progress_payload([0, 1, 0, 2])),
                                       RadioMessage(2, 5, progress_payload([0, 0, 3, 1]))])
        self.assertEqual(payload, progress_payload([0, 1, 3, 2]))

    def test_moves_on_once_everybody_reached_its_point(self):
        self.robot.reached = 1  # holding its first point
        self.robot.on_radio([RadioMessage(1, 5, progress_payload([0, 1, 1, 0]))])
        self.assertEqual(self.robot.goal_index, 0)  # robot 3 is not there yet
        self.robot.on_radio([RadioMessage(3, 35, progress_payload([0, 0, 2, 1]))])
        self.assertEqual(self.robot.goal_index, 1)

    def test_done_only_while_holding_the_last_point(self):
        # Pushed off its last point (HRVO stepping aside), a robot is not done until it is back.
        self.robot.reached, self.robot.goal_index = 2, 2  # heading for its last point, (0.85, 0)
        for x, done in [(0.83, True), (0.79, False), (0.84, True)]:
            self.robot.on_odometry(OdometryReading(1, np.array([x, 0.0, 0.0])))
            command = self.robot.update(1)
            self.assertEqual(self.robot.done(), done, f"at x = {x}")
            self.assertEqual(self.robot.reached, 3)
            if not done:
                self.assertGreater(command[0], 0.0)  # drives back

    def test_slows_down_in_proportion_to_the_distance_before_its_point(self):
        # As C++'s CircleFormationRobot: preferred speed min(max_speed_mps, gain * distance).
        self.robot.reached, self.robot.goal_index = 2, 2  # heading for (0.85, 0)
        for x, speed in [(-0.15, 0.2), (0.6, 0.2), (0.75, 0.8 * 0.1), (0.81, 0.8 * 0.04)]:
            self.robot.on_odometry(OdometryReading(1, np.array([x, 0.0, 0.0])))
            v, w = self.robot.update(1)
            self.assertAlmostEqual(v, 0.8 * speed, places=12, msg=f"at x = {x}")  # vel_gain 0.8
            self.assertAlmostEqual(w, 0.0, places=12)

    def test_drives_on_into_the_tolerance_until_stop_m_then_holds_until_pushed_out(self):
        self.robot.reached, self.robot.goal_index = 2, 2  # heading for (0.85, 0)
        # Reached within tolerance_m, it drives on to stop_m, holds, and is done only from there.
        for x, done, drives in [(0.81, False, True), (0.83, True, False), (0.805, True, False),
                                (0.79, False, True), (0.815, False, True), (0.835, True, False)]:
            self.robot.on_odometry(OdometryReading(1, np.array([x, 0.0, 0.0])))
            v, _ = self.robot.update(1)
            self.assertEqual(self.robot.done(), done, f"at x = {x}")
            self.assertEqual(v > 0.0, drives, f"at x = {x}")

    def test_stop_m_beyond_the_tolerance_is_an_error(self):
        # A setup error becomes the agent's fault, naming the key and both values.
        agents = hrvo_circle_world.circle_agents(4, params={"tolerance_m": 0.02, "stop_m": 0.03})
        self.assertIsNotNone(agents[0].fault)
        self.assertIn("stop_m must be > 0 and <= tolerance_m (0.02), got 0.03", str(agents[0].fault))

    def test_bad_payloads_are_counted_and_dropped(self):
        bad = [progress_payload([0, 1, 0]), progress_payload([0, 4, 0, 0]), progress_payload([0, 1, 0, 0]) + b"x",
               struct.pack("<5i", 5, 0, 0, 0, 0)]
        payload = self.robot.on_radio([RadioMessage(sender, 1, p) for sender, p in enumerate(bad, start=1)])
        self.assertEqual(payload, progress_payload([0, 0, 0, 0]))
        self.assertEqual(self.robot.bad_radio_messages, 4)


class CircleSwapScenario(unittest.TestCase):
    """Ten robots, the thesis's timers, pure-Python world: all three formations, no collision."""

    def run_circle(self, seed, variant):
        params = {"radius_m": 0.85, "formations": 3, "tolerance_m": 0.05, "max_speed_mps": 0.2,
                  "hrvo": {"variant": variant, "safety_radius_m": 0.24}}
        agents = hrvo_circle_world.circle_agents(10, seed=seed, params=params)
        result = hrvo_circle_world.run(agents, hrvo_circle_world.start_poses(10, seed), max_steps=4000)
        self.assertTrue(result.all_done, f"not done after {result.steps} steps")
        self.assertTrue(all(agent.robot.reached == 3 for agent in agents))
        self.assertEqual(result.collisions, 0)
        self.assertEqual(result.boundary_errors, 0)
        return result

    def test_exact_finishes_all_formations_without_collision(self):
        for seed in (1, 2):
            with self.subTest(seed=seed):
                result = self.run_circle(seed, "exact")
                self.assertGreater(result.min_distance_m, 0.2)  # the exact HRVO keeps its 0.24 m nearly everywhere

    def test_thesis_variant_finishes_all_formations_without_collision(self):
        self.run_circle(1, "thesis")


if __name__ == "__main__":
    unittest.main()
