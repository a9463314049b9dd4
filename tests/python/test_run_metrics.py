#!/usr/bin/python3
"""Unit tests of a Python controller's own goal and metrics (python/dream/run_metrics.py): the
declaration API (goal_points, metrics, goal classmethods), what it turns them into for
summary.json, its errors, and the file protocol the reporting tool uses.

Exit code 77 (skipped) when numpy is missing.
"""

import json
import os
import subprocess
import sys
import tempfile
import textwrap
import unittest

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_numpy

require_numpy()
import numpy as np  # noqa: E402
put_runtime_on_path()

from dream import Robot, key  # noqa: E402
from dream.run_metrics import MetricsDeclarationError, RunRecord, evaluate  # noqa: E402


class Pair(Robot):
    """Two robots meant to reach (+-0.5, 0)."""
    KEYS = {"tolerance_m": key(0.05, above=0.0)}

    @classmethod
    def goal_points(cls, config, num_robots):
        return [[(-0.5, 0.0)], [(0.5, 0.0)]]

    @classmethod
    def metrics(cls, run):
        errors = run.distances_to([p[0] for p in run.goal_points])
        return {"worst_error_m": errors.max(axis=1), "final_error_m": errors[-1], "steps_seen": len(run.steps)}

    @classmethod
    def goal(cls, run, metrics):
        arrived = metrics["worst_error_m"] < run.config["tolerance_m"]
        return {"met": bool(arrived[-1]), "completion_step": run.first_step_where(arrived), "detail": "pair"}


def poses_towards(end_x, steps=5):
    """(steps, 2, 3): robot 0 from (-1, 0) to (-end_x, 0), robot 1 mirrored."""
    xs = np.linspace(1.0, end_x, steps)
    poses = np.zeros((steps, 2, 3))
    poses[:, 0, 0] = -xs
    poses[:, 1, 0] = xs
    return np.arange(steps), poses


class DeclarationTest(unittest.TestCase):
    def test_met_goal_with_its_completion_step_and_figures(self):
        steps, poses = poses_towards(0.5)
        document = evaluate(Pair, {"tolerance_m": 0.05}, steps, poses)
        self.assertEqual(document["declared"], ["goal_points", "metrics", "goal"])
        self.assertEqual(document["goal"], {"met": True, "completion_step": 4, "detail": "pair"})
        self.assertEqual(document["goal_points"], [[[-0.5, 0.0]], [[0.5, 0.0]]])
        metrics = document["metrics"]
        self.assertEqual(metrics["steps_seen"], 5.0)
        self.assertEqual(len(metrics["worst_error_m"]), 5)  # a series: [step, value] per step
        self.assertEqual(metrics["worst_error_m"][0], [0, 0.5])
        self.assertEqual(metrics["final_error_m"], [0.0, 0.0])  # one per robot

    def test_missed_goal_has_no_completion_step(self):
        steps, poses = poses_towards(0.7)
        goal = evaluate(Pair, {"tolerance_m": 0.05}, steps, poses)["goal"]
        self.assertFalse(goal["met"])
        self.assertEqual(goal["completion_step"], -1)

    def test_a_class_that_declares_nothing_has_no_goal(self):
        class Plain(Robot):
            pass
        steps, poses = poses_towards(0.5)
        document = evaluate(Plain, {}, steps, poses)
        self.assertEqual(document, {"declared": [], "metrics": {}, "goal": None, "goal_points": []})

    def test_a_bool_goal(self):
        class Always(Robot):
            @classmethod
            def goal(cls, run, metrics):
                return run.num_robots == 2
        steps, poses = poses_towards(0.5)
        self.assertEqual(evaluate(Always, {}, steps, poses)["goal"],
                         {"met": True, "completion_step": -1, "detail": "met"})

    def test_bad_declarations_are_named(self):
        steps, poses = poses_towards(0.5)

        class WrongLength(Robot):
            @classmethod
            def metrics(cls, run):
                return {"odd": [1.0, 2.0, 3.0]}

        class NotFinite(Robot):
            @classmethod
            def metrics(cls, run):
                return {"bad": float("nan")}

        class BadGoal(Robot):
            @classmethod
            def goal(cls, run, metrics):
                return {"met": True, "when": 3}

        class Reserved(Robot):
            @classmethod
            def metrics(cls, run):
                return {"goal": 1.0}

        class BadPoints(Robot):
            @classmethod
            def goal_points(cls, config, num_robots):
                return [[(0, 0)]]

        for robot_class, words in ((WrongLength, "metrics()['odd']: 3 values"), (NotFinite, "not a finite number"),
                                   (BadGoal, "unknown keys ['when']"), (BadPoints, "one list of (x, y) per robot"),
                                   (Reserved, "'goal' is taken by summary.json's own fields")):
            with self.subTest(robot_class.__name__):
                with self.assertRaises(MetricsDeclarationError) as raised:
                    evaluate(robot_class, {}, steps, poses)
                self.assertIn(words, str(raised.exception))

    def test_first_step_where_needs_the_condition_to_hold_to_the_end(self):
        run = RunRecord(np.arange(10, 15), np.zeros((5, 1, 3)), {})
        self.assertEqual(run.first_step_where([False, True, False, True, True]), 13)
        self.assertEqual(run.first_step_where([True] * 5), 10)
        self.assertEqual(run.first_step_where([True, True, True, True, False]), -1)


class ProtocolTest(unittest.TestCase):
    """What dream run does: python3 -I run_metrics.py INPUT OUTPUT."""

    @staticmethod
    def spec_bytes(folder, module_text):
        """The controller spec the agents get, for class Pair of `module_text`."""
        module = os.path.join(folder, "pair.py")
        with open(module, "w") as f:
            f.write(module_text)
        return json.dumps({"format": 1, "name": "pair", "config_file": "pair.yaml", "robots": 2, "seed": 1,
                           "module": module, "class": "Pair", "section_line": 3, "module_line": 4,
                           "class_line": 5, "params": {},
                           "parts": {"robot": {"period_steps": [1, 1], "start_delay_steps": [0, 0],
                                               "vel_gain": 0.8, "ang_gain": 3.0},
                                     "sensors": [], "radio": {"kind": "none", "period_steps": [1, 1], "range_m": 1.0,
                                                               "graph": [], "leaders": [], "loss_probability": 0.0,
                                                               "delay_steps": 0}}}).encode()

    @staticmethod
    def script(folder, *args):
        """python3 -I run_metrics.py ARGS... OUTPUT: exit status, OUTPUT's document (or None), stderr."""
        script = os.path.join(SOURCE_DIR, "python", "dream", "run_metrics.py")
        output_path = os.path.join(folder, "output")
        done = subprocess.run([sys.executable, "-I", script, *args, output_path], capture_output=True, text=True,
                              timeout=60)
        output = None
        if done.returncode == 0:
            with open(output_path) as f:
                output = json.load(f)
        return done.returncode, output, done.stderr

    def run_script(self, module_text, poses):
        with tempfile.TemporaryDirectory() as folder:
            data = self.spec_bytes(folder, module_text)
            with open(os.path.join(folder, "input"), "wb") as f:
                f.write(json.dumps({"spec_bytes": len(data), "steps": poses.shape[0], "robots": 2}).encode() + b"\n")
                f.write(data)
                f.write(np.arange(poses.shape[0], dtype=np.int64).tobytes())
                f.write(poses.astype(np.float64).tobytes())
            return self.script(folder, os.path.join(folder, "input"))

    def goal_points(self, module_text, robots=2, header=None, cut=0):
        """--goal-points: the spec alone, before any run."""
        with tempfile.TemporaryDirectory() as folder:
            data = self.spec_bytes(folder, module_text)
            with open(os.path.join(folder, "input"), "wb") as f:
                f.write((header or json.dumps({"spec_bytes": len(data), "robots": robots}).encode()) + b"\n")
                f.write(data[:len(data) - cut])
            return self.script(folder, "--goal-points", os.path.join(folder, "input"))

    MODULE = textwrap.dedent('''
        from dream import Robot, key

        class Pair(Robot):
            KEYS = {"tolerance_m": key(0.05, above=0.0)}

            @classmethod
            def goal(cls, run, metrics):
                return bool(abs(abs(run.poses[-1, :, 0]) - 0.5).max() < run.config["tolerance_m"])
        ''')

    def test_the_script_reads_the_file_and_writes_the_goal(self):
        code, output, errors = self.run_script(self.MODULE, poses_towards(0.5)[1])
        self.assertEqual(code, 0, errors)
        self.assertTrue(output["goal"]["met"])
        code, output, errors = self.run_script(self.MODULE, poses_towards(0.8)[1])
        self.assertEqual(code, 0, errors)
        self.assertFalse(output["goal"]["met"])

    def test_an_exception_in_the_class_names_its_file_and_line(self):
        broken = self.MODULE.replace("return bool(", "raise RuntimeError('oops'); return bool(")
        code, output, errors = self.run_script(broken, poses_towards(0.5)[1])
        self.assertEqual(code, 1)
        self.assertIsNone(output)
        self.assertRegex(errors, r"RuntimeError: oops \(.*pair\.py:9\)")


    POINTS = textwrap.dedent('''
        from dream import Robot

        class Pair(Robot):
            @classmethod
            def goal_points(cls, config, num_robots):
                return [[(-0.5, 0.0)], [(0.5, 0.0), (0.5, 0.25)]][:num_robots] + [[]] * max(0, num_robots - 2)
        ''')

    def test_goal_points_alone_before_a_run(self):
        code, output, errors = self.goal_points(self.POINTS)
        self.assertEqual(code, 0, errors)
        self.assertEqual(output, {"declared": True, "goal_points": [[[-0.5, 0.0]], [[0.5, 0.0], [0.5, 0.25]]]})
        code, output, errors = self.goal_points(self.MODULE)  # declares a goal, but no points
        self.assertEqual(code, 0, errors)
        self.assertEqual(output, {"declared": False, "goal_points": []})

    def test_goal_points_errors_are_named(self):
        wrong = self.POINTS.replace("[:num_robots] + [[]] * max(0, num_robots - 2)", "")
        code, _, errors = self.goal_points(wrong, robots=3)
        self.assertEqual(code, 1)
        self.assertRegex(errors, r"pair\.py: Pair\.goal_points\(\): expected one list of \(x, y\) per robot \(3\)")
        many = self.POINTS.replace("[[(-0.5, 0.0)], [(0.5, 0.0), (0.5, 0.25)]]", "[[(0.0, 0.0)] * 1001, []]")
        code, _, errors = self.goal_points(many)
        self.assertEqual(code, 1)
        self.assertIn("goal_points()[0]: 1001 points; at most 1000 a robot", errors)
        code, _, errors = self.goal_points(self.POINTS, header=b"{not json")
        self.assertEqual(code, 1)
        self.assertIn("bad header line", errors)
        code, _, errors = self.goal_points(self.POINTS, robots=0)
        self.assertEqual(code, 1)
        self.assertIn("bad header", errors)
        code, _, errors = self.goal_points(self.POINTS, cut=10)
        self.assertEqual(code, 1)
        self.assertIn("cut short", errors)


if __name__ == "__main__":
    unittest.main()
