#!/usr/bin/python3
"""dream's Robotarium toolbox (python/dream/transformations.py, controllers.py, graph.py, misc.py)
against the official Robotarium V2 one (rps.utilities): tests/data/robotarium_v2_toolbox.json
holds the official outputs on random inputs (tests/robotarium_reference/generate_toolbox_reference.py);
with ROBOTARIUM_PYTHON_SIMULATOR naming a checkout, the official package is also called live on
fresh inputs. Closed-form functions agree to 1e-9; the random ones (graphs, poses, charger slots)
draw the same numbers from a seeded `random` and numpy stream, so they agree exactly.

Exit code 77 (skipped) when numpy is missing.
"""

import importlib.util
import math
import os
import random
import unittest

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_numpy

require_numpy()
import numpy as np  # noqa: E402
put_runtime_on_path()

from dream import controllers, graph, misc, transformations  # noqa: E402
from dream.toolbox_checks import ToolboxArgumentError  # noqa: E402

FIXTURE = os.path.join(SOURCE_DIR, "tests", "data", "robotarium_v2_toolbox.json")
GENERATOR = os.path.join(SOURCE_DIR, "tests", "robotarium_reference", "generate_toolbox_reference.py")
TOLERANCE = 1e-9
DREAM = {"transformations": transformations, "controllers": controllers, "graph": graph, "misc": misc}


def load_generator():
    spec = importlib.util.spec_from_file_location("generate_toolbox_reference", GENERATOR)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


reference = load_generator()


class Comparison:
    """Compares one recorded official result with dream's, naming the case."""

    def __init__(self, test):
        self.test = test

    def same(self, expected, actual, where, exact=False):
        if isinstance(expected, dict) and "error" in expected:
            self.test.assertIsInstance(actual, dict, "%s: the official call raised, dream's returned" % where)
            self.test.assertIn("error", actual, where)
        elif isinstance(expected, dict) and "tuple" in expected:
            self.test.assertIn("tuple", actual, where)
            self.test.assertEqual(len(expected["tuple"]), len(actual["tuple"]), where)
            for i, (e, a) in enumerate(zip(expected["tuple"], actual["tuple"])):
                self.same(e, a, "%s[%d]" % (where, i), exact)
        elif isinstance(expected, dict) and "array" in expected:
            self.test.assertIn("array", actual, where)
            self.test.assertEqual(expected["shape"], actual["shape"], where)
            self.test.assertEqual(expected["dtype"], actual["dtype"], where)
            e, a = reference.decode(expected), reference.decode(actual)
            if expected["dtype"] == "float" and not exact:
                np.testing.assert_allclose(a, e, rtol=0, atol=TOLERANCE, err_msg=where)
            else:
                np.testing.assert_array_equal(a, e, err_msg=where)
        elif isinstance(expected, float):
            self.test.assertTrue(math.isclose(expected, actual, rel_tol=0, abs_tol=TOLERANCE), where)
        else:
            self.test.assertEqual(expected, actual, where)

    def case_set(self, data):
        for index, case in enumerate(data["closed_form"]):
            calls = [[reference.decode(a) for a in args] for args in case["calls"]]
            got = reference.call_closed_form(DREAM, case["module"], case["factory"], case["kwargs"], calls,
                                             case["pick"])
            for k, (expected, actual) in enumerate(zip(case["results"], got)):
                self.same(expected, actual, "closed_form[%d] %s.%s call %d" % (index, case["module"],
                                                                                 case["factory"], k))
        for index, case in enumerate(data["seeded"]):
            got = reference.call_seeded(DREAM, case["module"], case["function"], case["args"], case["seed"])
            self.same(case["result"], got, "seeded[%d] %s.%s%s seed %d" % (index, case["module"], case["function"],
                                                                        tuple(case["args"]), case["seed"]), exact=True)


class RecordedReferenceTest(unittest.TestCase):
    def test_same_results_as_the_official_toolbox(self):
        import json
        with open(FIXTURE, encoding="utf-8") as f:
            data = json.load(f)
        self.assertGreaterEqual(len(data["closed_form"]), 200)
        self.assertGreaterEqual(len(data["seeded"]), 50)
        Comparison(self).case_set(data)


@unittest.skipUnless(os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR"),
                     "set ROBOTARIUM_PYTHON_SIMULATOR to a robotarium_python_simulator checkout")
class LiveReferenceTest(unittest.TestCase):
    def test_fresh_inputs_against_the_official_package(self):
        official = reference.official_toolbox(os.environ["ROBOTARIUM_PYTHON_SIMULATOR"])
        seed = random.SystemRandom().randrange(2 ** 31)
        with self.subTest(seed=seed):
            Comparison(self).case_set(reference.generate(official, seed, count=6))


class ArgumentTest(unittest.TestCase):
    """Bad arguments name the function, the argument and the value, and are AssertionErrors as
    the official ones are (a script catching those keeps working)."""

    def test_bad_gain_names_function_argument_and_value(self):
        with self.assertRaisesRegex(ToolboxArgumentError, r"create_si_to_uni_dynamics: linear_velocity_gain .* -1"):
            transformations.create_si_to_uni_dynamics(linear_velocity_gain=-1)
        with self.assertRaises(AssertionError):
            controllers.create_si_position_controller(x_velocity_gain=float("nan"))

    def test_wrong_shapes_name_the_argument_and_shape(self):
        si_to_uni = transformations.create_si_to_uni_dynamics()
        with self.assertRaisesRegex(ValueError, r"si_to_uni: states must be 3 x N, got shape \(2, 4\)"):
            si_to_uni(np.zeros((2, 4)), np.zeros((2, 4)))
        with self.assertRaisesRegex(ValueError, r"same number of columns \(4 vs 3\)"):
            si_to_uni(np.zeros((2, 4)), np.zeros((3, 3)))

    def test_neighbour_queries_refuse_an_agent_out_of_range(self):
        with self.assertRaisesRegex(ValueError, r"agent must be a robot index from 0 to 2, got 3"):
            graph.delta_disk_neighbors(np.zeros((2, 3)), 3, 1.0)
        with self.assertRaisesRegex(ValueError, r"L must be a square"):
            graph.topological_neighbors(np.zeros((2, 3)), 0)

    def test_more_charger_slots_than_there_are_is_refused(self):
        with self.assertRaisesRegex(ValueError, r"N must be at most 22"):
            misc.generate_initial_poses(23)

    def test_hybrid_controller_resets_phases_when_the_robot_count_changes(self):
        hybrid = controllers.create_pose_controller_hybrid()
        goals = np.array([[0.0, 0.5], [0.0, 0.0], [0.0, 0.0]])
        # Robot 0 on its position, turned away: it rotates and leaves the approach phase.
        states = np.array([[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]])
        self.assertEqual(hybrid(states, goals)[0, 0], 0.0)
        _, phases = hybrid(states, goals, in_approach_state=np.ones(2))
        self.assertEqual(phases[0], 0)

    def test_font_size_without_a_figure_says_why(self):
        class NoFigure:
            _fig = None
        with self.assertRaisesRegex(ValueError, r"no figure .* `dream view`"):
            misc.determine_font_size(NoFigure(), 0.1)


if __name__ == "__main__":
    unittest.main(verbosity=2)
