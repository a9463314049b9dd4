#!/usr/bin/python3
"""Unit tests of a Robotarium script run's goal (docs/robotarium-scripts.md#the-goal): DREAM's rps
keeps the script's last at_pose/at_position check (python/rps_dream/rps/_script_goal.py, tied to
robots by the poses get_poses() gave), and RobotariumScript (python/rps_dream/robotarium_script.py)
judges the run's logged poses by it, or by controller.goal_points / goal_poses.

Exit code 77 (skipped) when numpy is missing.
"""

import importlib.util
import json
import os
import tempfile
import unittest

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_numpy

require_numpy()
import numpy as np  # noqa: E402
put_runtime_on_path()

from dream import misc, transformations  # noqa: E402
from dream.controller_spec import check_key_value  # noqa: E402
from dream.run_metrics import evaluate  # noqa: E402


def load(name, path):
    spec = importlib.util.spec_from_file_location(name, os.path.join(SOURCE_DIR, path))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


script_goal = load("script_goal_under_test", "python/rps_dream/rps/_script_goal.py")
robotarium_script = load("robotarium_script_under_test", "python/rps_dream/robotarium_script.py")
RobotariumScript = robotarium_script.RobotariumScript


def config(**given):
    """RobotariumScript's checked keys, as the runtime gives them."""
    return {name: check_key_value(given.get(name, spec.default), spec, 2)
            for name, spec in RobotariumScript.KEYS.items()}


def run_ending_at(final, steps=4):
    """(steps, 2, 3) poses from (0, 0, 0) to `final` (2 x 3), linearly."""
    start = np.zeros((2, 3))
    poses = np.array([start + (final - start) * k / (steps - 1) for k in range(steps)])
    return np.arange(steps), poses


class RecordTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)

    def record(self):
        with open(os.path.join(self.folder.name, script_goal.RECORD_NAME)) as f:
            return json.load(f)

    def test_the_last_check_is_kept_with_its_robots_found_by_the_poses_the_script_saw(self):
        goal = script_goal.ScriptGoal(self.folder.name)
        goal.poses = np.array([[0.1, 0.2, 0.3], [0.0, -0.5, 0.5], [0.0, 0.0, 0.0]])
        at_pose = misc.create_at_pose(position_error=0.03, rotation_error=0.1)
        at_position = misc.create_at_position(position_error=0.07)
        misc.listen_to_checks(goal.on_check)
        self.addCleanup(misc._check_listeners.remove, goal.on_check)
        at_pose(goal.poses, np.ones((3, 3)))
        # Robots 2 and 0, in that order (a subset of the poses' columns): tied by their x, y.
        at_position(goal.poses[:2, [2, 0]], np.array([[1.0, 2.0], [3.0, 4.0]]))
        goal.save()
        last = self.record()["last_check"]
        self.assertEqual(last["check"], "at_position")
        self.assertEqual(last["robots"], [2, 0])
        self.assertEqual(last["targets"], [[1.0, 3.0], [2.0, 4.0]])
        self.assertEqual(last["position_error"], 0.07)
        self.assertIsNone(last["rotation_error"])
        self.assertEqual(self.record()["checks"], 2)

    def test_a_check_on_other_poses_is_tied_only_when_it_has_a_column_per_robot(self):
        goal = script_goal.ScriptGoal(self.folder.name)
        goal.poses = np.array([[0.1, 0.2], [0.0, -0.5], [0.0, 0.0]])
        goal.on_check("at_position", np.array([[9.0, 8.0], [7.0, 6.0]]), np.zeros((2, 2)), 0.05, None)
        self.assertEqual(goal.last["robots"], [0, 1])  # an estimate of every robot, in order
        goal.on_check("at_position", np.array([[9.0], [7.0]]), np.zeros((2, 1)), 0.05, None)
        self.assertIsNone(goal.last)  # one column matching no robot: no goal
        goal.save()
        self.assertIsNone(self.record()["last_check"])

    def test_a_check_on_the_points_ahead_of_the_robots_records_that_point(self):
        # The dead_reckoning example checks at_position on uni_to_si_states(x): a point 0.05 m ahead.
        goal = script_goal.ScriptGoal(self.folder.name)
        goal.poses = np.array([[0.1, 0.2, -0.4], [0.0, -0.5, 0.3], [0.3, -2.0, 3.1]])
        _, uni_to_si_states = transformations.create_si_to_uni_mapping(projection_distance=0.05)
        goal.on_check("at_position", uni_to_si_states(goal.poses), np.zeros((2, 3)), 0.1, None)
        self.assertEqual(goal.last["robots"], [0, 1, 2])
        self.assertEqual(goal.last["point_offset_m"], [0.05, 0.0])
        goal.on_check("at_position", goal.poses[:2], np.zeros((2, 3)), 0.1, None)
        self.assertIsNone(goal.last["point_offset_m"])  # their centres
        estimate = goal.poses[:2] + np.array([[0.01, -0.02, 0.0], [0.0, 0.01, 0.03]])
        goal.on_check("at_position", estimate, np.zeros((2, 3)), 0.1, None)
        self.assertIsNone(goal.last["point_offset_m"])  # estimates of the centres, not one point of each

    def test_an_earlier_runs_record_is_removed_when_the_script_makes_its_robotarium(self):
        path = os.path.join(self.folder.name, script_goal.RECORD_NAME)
        with open(path, "w") as f:
            f.write('{"last_check": null}')
        script_goal.ScriptGoal(self.folder.name)
        self.assertFalse(os.path.exists(path))


class JudgeTest(unittest.TestCase):
    def test_goal_poses_are_judged_as_at_pose_on_the_last_poses_with_headings_wrapped(self):
        targets = [[0.5, 0.0, np.pi - 0.01], [-0.5, 0.0, 0.0]]
        steps, poses = run_ending_at(np.array([[0.5, 0.0, -np.pi + 0.01], [-0.5, 0.04, 0.0]]))
        document = evaluate(RobotariumScript, config(goal_poses=targets), steps, poses)
        self.assertTrue(document["goal"]["met"], document)
        self.assertEqual(document["goal"]["completion_step"], 3)
        self.assertIn("controller.goal_poses", document["goal"]["detail"])
        self.assertEqual(document["goal_points"], [[[0.5, 0.0]], [[-0.5, 0.0]]])
        missed = evaluate(RobotariumScript, config(goal_poses=targets, position_error=0.03), steps, poses)
        self.assertFalse(missed["goal"]["met"])
        self.assertIn("worst 0.04 m", missed["goal"]["detail"])

    def test_the_scripts_record_is_the_goal_when_no_key_gives_one(self):
        with tempfile.TemporaryDirectory() as folder:
            record = os.path.join(folder, "script_goal.json")
            with open(record, "w") as f:
                json.dump({"last_check": {"check": "at_position", "robots": [1], "targets": [[0.2, 0.2]],
                                          "position_error": 0.05, "rotation_error": None}}, f)
            steps, poses = run_ending_at(np.array([[1.0, 1.0, 0.0], [0.2, 0.19, 0.0]]))
            document = evaluate(RobotariumScript, config(goal_record=record), steps, poses)
            self.assertTrue(document["goal"]["met"], document)
            self.assertIn("the script's last at_position check", document["goal"]["detail"])
            self.assertEqual(document["goal_points"], [[], [[0.2, 0.2]]])
            with open(record, "w") as f:
                json.dump({"last_check": {"check": "at_position", "robots": [5], "targets": [[0.2, 0.2]],
                                          "position_error": 0.05, "rotation_error": None}}, f)
            with self.assertRaisesRegex(robotarium_script.GoalError, r"robots \[5\] are not distinct robots"):
                evaluate(RobotariumScript, config(goal_record=record), steps, poses)

    def test_a_recorded_point_ahead_is_judged_on_that_point_of_the_logged_poses(self):
        with tempfile.TemporaryDirectory() as folder:
            record = os.path.join(folder, "script_goal.json")
            last = {"check": "at_position", "robots": [0, 1], "targets": [[0.55, 0.0], [0.0, 0.55]],
                    "position_error": 0.02, "rotation_error": None, "point_offset_m": [0.05, 0.0]}
            with open(record, "w") as f:
                json.dump({"last_check": last}, f)
            # The centres end 0.05 m short of the targets, facing them: their points ahead are on them.
            steps, poses = run_ending_at(np.array([[0.5, 0.0, 0.0], [0.0, 0.5, np.pi / 2]]))
            document = evaluate(RobotariumScript, config(goal_record=record), steps, poses)
            self.assertTrue(document["goal"]["met"], document)
            self.assertIn("0.05 m ahead", document["goal"]["detail"])
            last["point_offset_m"] = None  # judged on the centres: 0.05 m off
            with open(record, "w") as f:
                json.dump({"last_check": last}, f)
            self.assertFalse(evaluate(RobotariumScript, config(goal_record=record), steps, poses)["goal"]["met"])
            last["point_offset_m"] = [0.05, float("nan")]
            with open(record, "w") as f:
                json.dump({"last_check": last}, f)
            with self.assertRaisesRegex(robotarium_script.GoalError, r"point_offset_m"):
                evaluate(RobotariumScript, config(goal_record=record), steps, poses)

    def test_no_key_and_no_record_declare_no_goal(self):
        steps, poses = run_ending_at(np.zeros((2, 3)))
        document = evaluate(RobotariumScript, config(goal_record="/nonexistent/script_goal.json"), steps, poses)
        self.assertIsNone(document["goal"])
        self.assertEqual(document["metrics"], {})

    def test_bad_goal_keys_are_named(self):
        with self.assertRaisesRegex(robotarium_script.GoalError, r"controller.goal_points: expected one \[x, y\] per "
                                                                 r"robot \(2\), got 1"):
            RobotariumScript.declared_goal(config(goal_points=[[0, 0]]), 2)
        with self.assertRaisesRegex(robotarium_script.GoalError, r"controller.goal_poses\[1\]: expected 3 finite"):
            RobotariumScript.declared_goal(config(goal_poses=[[0, 0, 0], [0, float("nan"), 0]]), 2)
        with self.assertRaisesRegex(robotarium_script.GoalError, "give one of them"):
            RobotariumScript.declared_goal(config(goal_points=[[0, 0], [1, 1]], goal_poses=[[0, 0, 0], [1, 1, 1]]), 2)


if __name__ == "__main__":
    unittest.main()
