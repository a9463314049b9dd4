#!/usr/bin/python3
"""Unit tests of the pure-Python controller runtime (python/dream/) against the C++ parts'
semantics (agents/src/*.cc): timer, mailbox and mix_seed, sensors, motion, agent, spec.

Exit code 77 (skipped) when numpy is missing.
"""

import json
import math
import os
import re
import tempfile
import textwrap
import unittest

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_numpy

require_numpy()
import numpy as np  # noqa: E402
put_runtime_on_path()

from dream import (ActuatorLimits, ConfigError, ControllerFault, ControllerSpec, GraphRadio, Mailbox,  # noqa: E402
                   MovementSensor, ObstacleSensor, ObstacleView, OdometrySensor, RadioMessage, RangeRadio,
                   Robot, RobotAgent, RobotLimits, RobotParams, RoleRadio, SingleIntegratorToUnicycle, Timer,
                   WorldSnapshot, check, dxi_to_dxu, mix_seed, pack_floats, unpack_floats)
import dream  # noqa: E402
from dream.hrvo import HrvoParams  # noqa: E402
from dream.robot import did_you_mean  # noqa: E402

STEP_S = 0.033


def world(step, poses, velocities=None, obstacles=()):
    poses = np.array(poses, dtype=float)
    if velocities is None:
        velocities = np.zeros((len(poses), 2))
    return WorldSnapshot(step, poses, np.array(velocities, dtype=float), obstacles)


class Recorder(Robot):
    """Keeps every callback in `calls`; update returns (step, 0)."""

    def setup(self):
        self.calls = []

    def on_odometry(self, reading):
        super().on_odometry(reading)
        self.calls.append(("odometry", reading.step))

    def on_movement(self, reading):
        super().on_movement(reading)
        self.calls.append(("movement", reading.step))

    def on_radio(self, heard):
        self.calls.append(("radio", [(m.sender_id, m.sent_step) for m in heard]))
        return pack_floats([self.id, len(heard)])

    def update(self, step):
        self.calls.append(("update", step))
        return (float(step), 0.0)


def recorder(robot_id=0, num_robots=2):
    robot = Recorder(robot_id, RobotParams(), {}, num_robots)
    robot.setup()
    return robot


class TimerTest(unittest.TestCase):
    def test_runs_after_the_start_delay_every_period(self):
        timer = Timer(20, [4])
        self.assertEqual([step for step in range(31) if timer.tick(step)[0]], [21, 25, 29])

    def test_nothing_runs_at_step_zero(self):
        timer = Timer(0, [1, 3])
        due = [list(timer.tick(step)) for step in range(5)]
        self.assertEqual(due, [[False, False], [True, False], [True, False], [True, True], [True, False]])

    def test_rejects_bad_periods(self):
        with self.assertRaisesRegex(ValueError, "period of component 1 must be >= 1 step, got 0"):
            Timer(0, [1, 0])
        with self.assertRaisesRegex(ValueError, "start_delay_steps must be >= 0, got -1"):
            Timer(-1, [1])


class MixSeedAndMailboxTest(unittest.TestCase):
    def test_mix_seed_matches_cpp(self):
        # NoiseSource::MixSeed values printed by a small C++ program compiled with
        # g++ -std=c++17 -I agents/include, which includes dream/agents/framework/noise_source.h.
        self.assertEqual(mix_seed(1, 0, 0), 770544052526001461)
        self.assertEqual(mix_seed(1, 3, 2), 4082488131637046672)
        self.assertEqual(mix_seed(42, 7, 1000), 4214736301870392316)
        self.assertEqual(mix_seed(2 ** 64 - 1, 2 ** 64 - 1, 5), 8185103555570268672)

    def test_loss_matches_cpp(self):
        # The same C++ program: for seed MixSeed(1, 2, 0), sender 1, steps 0..19 and loss 0.5,
        # whether Mailbox::Post loses the message (1) or keeps it (0).
        cpp_lost = "01011110100111011110"
        mailbox = Mailbox(loss_probability=0.5, seed=mix_seed(1, 2, 0))
        radio = GraphRadio([[0, 1], [1, 0]])
        kept = []
        for step in range(20):
            mailbox.post(RadioMessage(1, step, b""))
            heard = mailbox.heard(radio, 0, world(step + 1, [[0, 0, 0], [1, 0, 0]]))
            kept.append("0" if heard and heard[0].sent_step == step else "1")
        self.assertEqual("".join(kept), cpp_lost)
        self.assertEqual(mailbox.lost_messages, cpp_lost.count("1"))

    def test_delay_and_newest_audible(self):
        mailbox = Mailbox(delay_steps=2)
        radio = GraphRadio([[0, 1], [1, 0]])
        poses = [[0, 0, 0], [1, 0, 0]]
        for step in range(10):
            mailbox.post(RadioMessage(1, step, bytes([step])))
        # Sent at k, heard from k + 1 + 2; only the newest delay + 2 = 4 are kept (6..9).
        self.assertEqual(mailbox.heard(radio, 0, world(12, poses))[0].sent_step, 9)
        self.assertEqual(mailbox.heard(radio, 0, world(11, poses))[0].sent_step, 8)
        self.assertEqual(mailbox.heard(radio, 0, world(9, poses))[0].sent_step, 6)
        self.assertEqual(mailbox.heard(radio, 0, world(8, poses)), [])

    def test_heard_by_sender_id_and_radio(self):
        mailbox = Mailbox()
        for sender in (3, 1, 2):
            mailbox.post(RadioMessage(sender, 0, b""))
        poses = [[0, 0, 0], [0.5, 0, 0], [1.5, 0, 0], [-0.9, 0, 0]]
        snapshot = world(1, poses)
        self.assertEqual([m.sender_id for m in mailbox.heard(RangeRadio(1.0), 0, snapshot)], [1, 3])
        graph = [[0, 0, 1, 1], [1, 0, 0, 0], [1, 0, 0, 0], [1, 0, 0, 0]]
        self.assertEqual([m.sender_id for m in mailbox.heard(GraphRadio(graph), 0, snapshot)], [2, 3])
        self.assertEqual(mailbox.heard(RoleRadio(True, graph), 0, snapshot), [])
        self.assertEqual([m.sender_id for m in mailbox.heard(RoleRadio(False, graph), 0, snapshot)], [2, 3])

    def test_rejects_bad_link(self):
        with self.assertRaisesRegex(ValueError, r"loss_probability must be in \[0, 1\), got 1"):
            Mailbox(loss_probability=1.0)

    def test_payload_helpers_round_trip(self):
        payload = pack_floats([[1.5, -2.0], [3.0, 0.25]])
        self.assertEqual(payload[:8], b"\x00\x00\x00\x00\x00\x00\xf8\x3f")  # 1.5, little-endian
        np.testing.assert_array_equal(unpack_floats(payload), [1.5, -2.0, 3.0, 0.25])
        with self.assertRaisesRegex(ValueError, "multiple of 8"):
            unpack_floats(b"\x00" * 7)


class SensorTest(unittest.TestCase):
    def test_odometry_wraps_theta_and_draws_no_noise_at_zero_std(self):
        robot = recorder()
        OdometrySensor().sense(world(3, [[0.1, 0.2, 3.5], [0, 0, 0]]), robot)
        np.testing.assert_array_equal(robot.pose, [0.1, 0.2, math.atan2(math.sin(3.5), math.cos(3.5))])
        self.assertAlmostEqual(robot.pose[2], 3.5 - 2 * math.pi, places=15)
        self.assertTrue(robot.has_odometry)

    def test_noise_repeats_for_the_same_seed(self):
        snapshot = world(0, [[0.1, 0.2, 0.3], [0, 0, 0]])
        readings = []
        for _ in range(2):
            robot = recorder()
            OdometrySensor(noise_std=0.01, seed=mix_seed(1, 0, 1)).sense(snapshot, robot)
            readings.append(robot.pose)
        np.testing.assert_array_equal(readings[0], readings[1])
        expected = np.array([0.1, 0.2, 0.3]) + np.random.Generator(np.random.PCG64(mix_seed(1, 0, 1))).normal(0, 0.01, 3)
        np.testing.assert_array_equal(readings[0], expected)

    def test_movement_range_field_of_view_and_order(self):
        # Robot 0 at the origin heading +y (pi/2); field of view 90 degrees straight ahead.
        poses = [[0, 0, math.pi / 2],
                 [0.5, 0.0, 0],          # 90 degrees to the right: outside the view
                 [0.0, 1.0, 0],          # straight ahead at exactly the range: seen
                 [0.1, 0.3, 0],          # 18 degrees right of ahead: seen
                 [0.0, 1.0001, 0],       # just out of range
                 [0.0, 0.0, 0]]          # on top of the robot: distance 0 is never a neighbour
        robot = recorder(num_robots=len(poses))
        MovementSensor(range_m=1.0, field_of_view_rad=math.pi / 2).sense(world(7, poses), robot)
        neighbours = robot.movement.neighbours
        self.assertEqual(len(neighbours), 2)
        self.assertEqual(robot.movement.step, 7)
        self.assertEqual(neighbours[0].distance_m, 1.0)
        self.assertAlmostEqual(neighbours[0].bearing_rad, math.pi / 2)
        np.testing.assert_allclose(neighbours[1].relative_position(), [0.1, 0.3])

    def test_movement_full_circle_as_written_sees_behind(self):
        poses = [[0, 0, 0], [-0.5, 0, 0], [0.5, 0, 0]]
        robot = recorder(num_robots=3)
        MovementSensor(field_of_view_rad=6.2832).sense(world(0, poses), robot)
        self.assertEqual([round(n.bearing_rad, 6) for n in robot.movement.neighbours], [round(math.pi, 6), 0.0])
        with self.assertRaisesRegex(ValueError, r"field_of_view_rad must be in \(0, 2 pi = 6.2832\], got 6.3"):
            MovementSensor(field_of_view_rad=6.3)

    def test_movement_velocity_of_the_point_ahead(self):
        # Neighbour heading +y driving v = 0.1 m/s, w = 1 rad/s: the point 0.05 m ahead moves
        # (cos th v - 0.05 sin th w, sin th v + 0.05 cos th w) = (-0.05, 0.1).
        robot = recorder()
        MovementSensor().sense(world(1, [[0, 0, 0], [0.3, 0, math.pi / 2]], [[0, 0], [0.1, 1.0]]), robot)
        np.testing.assert_allclose(robot.movement.neighbours[0].velocity_mps, [-0.05, 0.1], atol=1e-15)

    def test_obstacle_closest_point_and_range(self):
        obstacles = [ObstacleView(0, (1.0, 0.0), (0.4, 0.2)),      # closest point (0.8, 0), 0.8 m away
                     ObstacleView(1, (0.0, 2.0), (0.2, 0.2))]      # 1.9 m away: out of range
        robot = recorder(num_robots=1)
        ObstacleSensor(range_m=1.0).sense(world(2, [[0, 0, 0]], obstacles=obstacles), robot)
        self.assertEqual(len(robot.obstacles.closest_points_m), 1)
        np.testing.assert_array_equal(robot.obstacles.closest_points_m[0], [0.8, 0.0])
        np.testing.assert_array_equal(robot.obstacles.rectangles[0].center_m, [1.0, 0.0])
        np.testing.assert_array_equal(robot.obstacles.rectangles[0].size_m, [0.4, 0.2])


class MotionTest(unittest.TestCase):
    def test_dxi_to_dxu_at_nonzero_headings(self):
        params = RobotParams()
        # Heading +y, target +x: v = 0.8 (c 0.1) ~ 0, w = 3 atan2(-0.1, ~0) / (pi/2) = -3.
        v, w = dxi_to_dxu((0.1, 0.0), math.pi / 2, params)
        self.assertAlmostEqual(v, 0.0, places=15)
        self.assertAlmostEqual(w, -3.0, places=12)
        # Heading pi/3, dxi (0.1, 0.05): c = 0.5, s = sqrt(3)/2.
        c, s = 0.5, math.sqrt(3) / 2
        v, w = dxi_to_dxu((0.1, 0.05), math.pi / 3, params)
        v_expected = 0.8 * (c * 0.1 + s * 0.05)
        self.assertAlmostEqual(v, v_expected, places=15)
        self.assertAlmostEqual(w, 3.0 * math.atan2(-s * 0.1 + c * 0.05, v_expected) / (math.pi / 2), places=12)

    def test_robot_dxi_to_dxu_uses_the_odometry_heading(self):
        robot = recorder()
        OdometrySensor().sense(world(1, [[0, 0, math.pi / 2], [1, 1, 0]]), robot)
        self.assertEqual(robot.dxi_to_dxu((0.1, 0.0)), dxi_to_dxu((0.1, 0.0), math.pi / 2, robot.params))

    def test_actuator_limits(self):
        limits = ActuatorLimits()
        w_max = 2.0 * (0.016 / 0.11) * (0.2 / 0.016)
        self.assertEqual(limits.apply((0.5, 0.0)), (0.2, 0.0))
        self.assertEqual(limits.apply((-0.1, -10.0))[1], -w_max)
        self.assertEqual(limits.apply((float("nan"), 1.0)), (0.0, 0.0))
        # v = 0.2, w = 2: the outer wheel needs 0.2/0.016 + (0.11/0.032) 2 = 19.375 > 12.5 rad/s,
        # so |v| shrinks to (12.5 - 6.875) 0.016 = 0.09, a hair inside, sign kept.
        v, w = limits.apply((-0.2, 2.0))
        self.assertAlmostEqual(v, -0.09 * (1.0 - 1e-9), places=15)
        self.assertLess(abs(v), 0.09)
        self.assertEqual(w, 2.0)

    def test_si_to_uni_turns_at_the_limit_when_90_degrees_off(self):
        v, w = SingleIntegratorToUnicycle().map((0.0, 0.1), 0.0)
        self.assertEqual((v, w), (0.0, math.pi))
        with self.assertRaisesRegex(ValueError, "linear_gain must be positive"):
            SingleIntegratorToUnicycle(linear_gain=0.0)


class RobotariumNumbersTest(unittest.TestCase):
    """The Python runtime runs on the lab without the C++ package, so it writes the Robotarium's
    numbers again; they must stay those of base/robotarium's RobotariumConstants (the C++ agents'
    one source), read here from the header itself."""

    @classmethod
    def setUpClass(cls):
        header = os.path.join(SOURCE_DIR, "base", "robotarium", "include", "dream", "robotarium",
                              "robotarium_constants.h")
        with open(header, encoding="utf-8") as f:
            text = f.read()
        cls.k = {name: float(value) for name, value in
                 re.findall(r"static constexpr double (k\w+) = (-?[0-9.]+);", text)}
        for name in ("kMaxLinearVelocityMps", "kWheelRadiusMeters", "kBaseLengthMeters", "kRobotDiameterMeters",
                     "kArenaXMinMeters", "kArenaXMaxMeters", "kArenaYMinMeters", "kArenaYMaxMeters",
                     "kTimeStepSeconds"):
            if name not in cls.k:
                raise AssertionError(f"{header} has no literal {name} any more: update this test")

    def test_robot_limits_are_the_robotariums(self):
        k = self.k
        limits = RobotLimits()
        self.assertEqual(limits.max_linear_speed_mps, k["kMaxLinearVelocityMps"])
        self.assertEqual(limits.wheel_radius_m, k["kWheelRadiusMeters"])
        self.assertEqual(limits.base_length_m, k["kBaseLengthMeters"])
        # The header's own expressions for the derived limits (the official simulator's).
        self.assertEqual(limits.max_wheel_speed_radps, k["kMaxLinearVelocityMps"] / k["kWheelRadiusMeters"])
        self.assertEqual(limits.max_angular_speed_radps,
                         2.0 * (k["kWheelRadiusMeters"] / k["kRobotDiameterMeters"]) *
                         (k["kMaxLinearVelocityMps"] / k["kWheelRadiusMeters"]))

    def test_hrvo_arena_is_the_robotariums(self):
        k = self.k
        params = HrvoParams()
        self.assertEqual((params.x_min_m, params.x_max_m, params.y_min_m, params.y_max_m),
                         (k["kArenaXMinMeters"], k["kArenaXMaxMeters"], k["kArenaYMinMeters"],
                          k["kArenaYMaxMeters"]))


class RobotAgentTest(unittest.TestCase):
    def test_order_periods_and_repeated_command(self):
        robot = recorder()
        agent = RobotAgent(robot, [(OdometrySensor(), 1), (MovementSensor(), 2)], GraphRadio([[0, 1], [1, 0]]),
                           robot_period_steps=3, radio_period_steps=2)
        agent.receive(RadioMessage(1, 0, b"x"))
        agent.receive(RadioMessage(0, 0, b"own"))  # ignored
        outputs = [agent.step(world(step, [[0, 0, 0], [0.5, 0, 0]])) for step in range(5)]
        self.assertEqual(robot.calls, [("odometry", 1), ("odometry", 2), ("movement", 2), ("radio", [(1, 0)]),
                                       ("odometry", 3), ("update", 3), ("odometry", 4), ("movement", 4),
                                       ("radio", [(1, 0)])])
        self.assertEqual([output.v for output in outputs], [0.0, 0.0, 0.0, 3.0, 3.0])
        np.testing.assert_array_equal(unpack_floats(outputs[2].broadcast), [0.0, 1.0])
        self.assertIsNone(outputs[1].broadcast)

    def test_leader_publishes_but_hears_nothing(self):
        robot = recorder()
        agent = RobotAgent(robot, [], RoleRadio(True, [[0, 1], [1, 0]]))
        agent.receive(RadioMessage(1, 0, b""))
        output = agent.step(world(1, [[0, 0, 0], [0.5, 0, 0]]))
        self.assertEqual(robot.calls[0], ("radio", []))
        self.assertIsNotNone(output.broadcast)


class SpecFixture(unittest.TestCase):
    """Writes controller modules into a temporary folder and makes spec JSON for them."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)

    def module(self, name, source):
        path = os.path.join(self.folder.name, name)
        with open(path, "w") as file:
            file.write(textwrap.dedent(source))
        return path

    @staticmethod
    def spec(module, class_name, params, robots=2, sensors=None, radio=None, seed=1):
        sensors = sensors if sensors is not None else [
            {"kind": "odometry", "period_steps": [1] * robots, "noise_std": 0.0}]
        radio = radio if radio is not None else {
            "kind": "none", "period_steps": [1] * robots, "range_m": 1.0, "graph": [], "leaders": [],
            "loss_probability": 0.0, "delay_steps": 0}
        return {"format": 1, "name": "test", "config_file": "run.yaml", "robots": robots, "seed": seed,
                "module": module, "class": class_name, "section_line": 20, "module_line": 21, "class_line": 22,
                "params": {name: {"value": value, "line": line} for name, (value, line) in params.items()},
                "parts": {"robot": {"period_steps": [1] * robots, "start_delay_steps": [0] * robots,
                                    "vel_gain": 0.8, "ang_gain": 3.0},
                          "sensors": sensors, "radio": radio}}


GO_TO_GOAL = os.path.join(SOURCE_DIR, "config", "python", "go_to_goal.py")


class DidYouMeanTest(unittest.TestCase):
    """The same answers as C++'s config::DidYouMean (tests/config/name_suggestion_test.cc)."""

    KEYS = ["spacing_m", "gain", "max_speed_mps", "tolerance_m", "resume_m"]

    def test_a_typo_gets_the_closest_name(self):
        for given, name in [("tolerence_m", "tolerance_m"), ("max_sped_mps", "max_speed_mps"), ("gian", "gain"),
                            ("Spacing_M", "spacing_m"), ("spacing", "spacing_m")]:
            self.assertEqual(did_you_mean(given, self.KEYS), f" (did you mean '{name}'?)", given)

    def test_nothing_close_gets_no_suggestion(self):
        for given in ["bogus", "gxyz", "", "ga", "gain", "g" * 10000]:
            self.assertEqual(did_you_mean(given, self.KEYS), "", given[:20])
        self.assertEqual(did_you_mean("gain", []), "")


class SpecErrorTest(SpecFixture):
    def assert_config_error(self, spec, message):
        with self.assertRaises(ConfigError) as caught:
            ControllerSpec.from_json(json.dumps(spec))
        self.assertEqual(str(caught.exception), message)

    def go_to_goal(self, **params):
        params.setdefault("goals", ([[0.1, 0.2], [0.3, 0.4]], 23))
        return self.spec(GO_TO_GOAL, "GoToGoal", params)

    def test_own_key_errors_name_file_line_and_key(self):
        self.assert_config_error(self.go_to_goal(gian=(0.5, 24)),
                                 "run.yaml:24: controller.gian: unknown key for kind python class GoToGoal (did you "
                                 "mean 'gain'?); allowed keys here: kind, module, class, robot, sensors, radio, goals, "
                                 "gain, max_speed_mps, tolerance_m, goal_tolerance_m")
        # A key --set added has no line: the file alone, as C++'s ConfigNode says it.
        self.assert_config_error(self.go_to_goal(bogus=(0.5, 0)),
                                 "run.yaml: controller.bogus: unknown key for kind python class GoToGoal; allowed "
                                 "keys here: kind, module, class, robot, sensors, radio, goals, gain, max_speed_mps, "
                                 "tolerance_m, goal_tolerance_m")
        self.assert_config_error(self.go_to_goal(bogus=(0.5, 24)),
                                 "run.yaml:24: controller.bogus: unknown key for kind python class GoToGoal; allowed "
                                 "keys here: kind, module, class, robot, sensors, radio, goals, gain, max_speed_mps, "
                                 "tolerance_m, goal_tolerance_m")
        self.assert_config_error(self.spec(GO_TO_GOAL, "GoToGoal", {}),
                                 "run.yaml:20: controller.goals: required by class GoToGoal; missing here")
        self.assert_config_error(self.go_to_goal(gain=(-1, 25)), "run.yaml:25: controller.gain: must be > 0, got -1")
        self.assert_config_error(self.go_to_goal(max_speed_mps=(0.3, 26)),
                                 "run.yaml:26: controller.max_speed_mps: must be in (0, 0.2], got 0.3")
        self.assert_config_error(self.go_to_goal(gain=(True, 25)),
                                 "run.yaml:25: controller.gain: expected a number, got true")
        self.assert_config_error(self.go_to_goal(goals=([[0.1, 0.2]], 23)),
                                 "run.yaml:23: controller.goals: expected one [x, y] per robot (2), got 1")
        self.assert_config_error(self.go_to_goal(goals=([[0.1, 0.2], [0.3, "a"]], 23)),
                                 "run.yaml:23: controller.goals[1]: expected [x, y] in metres, finite numbers, "
                                 "got a list")

    def test_key_kinds(self):
        module = self.module("kinds.py", """
            from dream import Robot, key

            class Kinds(Robot):
                KEYS = {"count": key(2, kind="int", at_least=1),
                        "mode": key("fast", kind="string", choices=("fast", "slow")),
                        "weights": key(kind="matrix"),
                        "offsets": key(0.0, per_robot=True, below=1.0)}

                def update(self, step):
                    return (0.0, 0.0)
            """)
        spec = ControllerSpec.from_json(json.dumps(self.spec(module, "Kinds", {
            "weights": ([[0, 1], [1, 0]], 21), "offsets": ([0.5, -0.5], 22)})))
        self.assertEqual(spec.config["count"], 2)
        self.assertEqual(spec.config["offsets"], [0.5, -0.5])
        self.assertEqual(spec.config["weights"].shape, (2, 2))
        self.assert_config_error(self.spec(module, "Kinds", {"weights": ([[0]], 21), "count": (1.5, 22)}),
                                 "run.yaml:22: controller.count: expected a whole number, got 1.5")
        self.assert_config_error(self.spec(module, "Kinds", {"weights": ([[0]], 21), "mode": ("slowly", 23)}),
                                 "run.yaml:23: controller.mode: must be one of 'fast', 'slow', got 'slowly'")
        self.assert_config_error(self.spec(module, "Kinds", {"weights": ([[0]], 21), "mode": ("fsat", 23)}),
                                 "run.yaml:23: controller.mode: must be one of 'fast', 'slow', got 'fsat' (did you "
                                 "mean 'fast'?)")
        self.assert_config_error(self.spec(module, "Kinds", {"weights": ([[0, 1], [1]], 21)}),
                                 "run.yaml:21: controller.weights[1]: row 1 has 1 entries, row 0 has 2")
        self.assert_config_error(self.spec(module, "Kinds", {"weights": ([[0]], 21), "offsets": ([0.5, 1.0], 24)}),
                                 "run.yaml:24: controller.offsets[1]: must be < 1, got 1")

    def test_module_and_class_errors(self):
        self.assert_config_error(self.spec(os.path.join(self.folder.name, "absent.py"), "X", {}),
                                 f"run.yaml:21: controller.module: no controller module at "
                                 f"{os.path.join(self.folder.name, 'absent.py')}")
        self.assert_config_error(self.spec(GO_TO_GOAL, "GoToGaol", {}),
                                 f"run.yaml:22: controller.class: 'GoToGaol' is not in {GO_TO_GOAL}; Robot "
                                 f"subclasses there: GoToGoal")
        broken = self.module("broken.py", "import math\nmath.sqrt(-1)\n")
        with self.assertRaisesRegex(ConfigError, r"controller.module: cannot load .*broken.py: .*broken.py:2: "
                                                 r"in <module>: ValueError: math domain error"):
            ControllerSpec.from_json(json.dumps(self.spec(broken, "X", {})))

    def test_spec_errors_name_the_field(self):
        spec = self.go_to_goal()
        spec["robots"] = "two"
        self.assert_config_error(spec, "controller spec: robots: expected a whole number, got 'two'")
        spec = self.go_to_goal()
        spec["parts"]["robot"]["period_steps"] = [1]
        self.assert_config_error(spec, "controller spec: parts.robot.period_steps: expected a list with one "
                                       "entry per robot (2), got 1")
        spec = self.go_to_goal()
        spec["parts"]["sensors"] = [{"kind": "obstacle", "period_steps": [1, 1], "range_m": -1, "noise_std": 0}]
        self.assert_config_error(spec, "controller spec: parts.sensors[0]: range_m must be > 0, got -1")
        spec = self.go_to_goal()
        spec["extra"] = 1
        self.assertRaisesRegex(ConfigError, "controller spec: extra: unknown field", ControllerSpec.from_json,
                               json.dumps(spec))


    def test_spec_nested_too_deeply_is_a_config_error_not_a_recursion(self):
        # Issue 23: an edited spec of deeply nested JSON failed with a RecursionError's traceback.
        deep = "[" * 100000 + "]" * 100000
        self.assertRaisesRegex(ConfigError, r"^controller spec: nested more than 128 levels deep",
                               ControllerSpec.from_json, deep)
        spec = self.go_to_goal()
        spec["params"]["goal"] = {"value": json.loads("[" * 129 + "]" * 129), "line": 3}
        self.assertRaisesRegex(ConfigError, "nested more than 128 levels deep", ControllerSpec.from_json,
                               json.dumps(spec))
        # Brackets inside strings are text, not nesting.
        spec = self.go_to_goal()
        spec["name"] = "[{" * 200 + '\\"'
        self.assertEqual(ControllerSpec.from_json(json.dumps(spec)).num_robots, 2)

class ControllerFaultTest(SpecFixture):
    def test_fault_names_the_users_line_even_through_a_helper(self):
        self.module("faulty_helper.py", """
            def divide(a, b):
                return a / b
            """)
        module = self.module("faulty.py", """
            from dream import Robot
            from faulty_helper import divide


            class Faulty(Robot):
                def update(self, step):
                    return (divide(1.0, 0.0), 0.0)
            """)
        agent = ControllerSpec.from_json(json.dumps(self.spec(module, "Faulty", {}))).make_agent(1)
        agent.step(world(0, [[0, 0, 0], [1, 0, 0]]))  # step 0: update is not due yet
        expected = f"{module}:8: in update: ZeroDivisionError: float division by zero"
        for step in (1, 2):  # the fault stays
            with self.assertRaises(ControllerFault) as caught:
                agent.step(world(step, [[0, 0, 0], [1, 0, 0]]))
            self.assertEqual(str(caught.exception), expected)

    def test_an_oversize_radio_payload_is_the_controllers_fault_at_its_on_radio(self):
        # Issue 23: a 100 KB payload was sent, every receiver dropped it, and the run was clean.
        module = self.module("loud.py", """
            from dream import Robot


            class Loud(Robot):
                def on_radio(self, heard):
                    return b"x" * 100000

                def update(self, step):
                    return (0.0, 0.0)


            class JustRight(Loud):
                def on_radio(self, heard):
                    return b"x" * 65536
            """)
        radio = {"kind": "range", "period_steps": [1, 1], "range_m": 1.0, "graph": [], "leaders": [],
                 "loss_probability": 0.0, "delay_steps": 0}
        agent = ControllerSpec.from_json(json.dumps(self.spec(module, "Loud", {}, radio=radio))).make_agent(0)
        with self.assertRaises(ControllerFault) as caught:
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))
        self.assertEqual(str(caught.exception),
                         f"{module}:6: in on_radio: ValueError: a radio payload of 100000 bytes is over the limit "
                         f"of 65536 bytes: every receiver would drop it. Send less, e.g. fewer or smaller fields")
        agent = ControllerSpec.from_json(json.dumps(self.spec(module, "JustRight", {}, radio=radio))).make_agent(0)
        self.assertEqual(len(agent.step(world(1, [[0, 0, 0], [1, 0, 0]])).broadcast), 65536)

    def test_bad_update_result_and_setup_fault(self):
        module = self.module("bad.py", """
            from dream import Robot


            class NoCommand(Robot):
                def update(self, step):
                    return None


            class NotFinite(Robot):
                def update(self, step):
                    return (0.1, float("nan"))


            class BadSetup(Robot):
                def setup(self):
                    raise RuntimeError("no goal for robot %d" % self.id)

                def update(self, step):
                    return (0.0, 0.0)
            """)
        agent = ControllerSpec.from_json(json.dumps(self.spec(module, "NoCommand", {}))).make_agent(0)
        with self.assertRaisesRegex(ControllerFault, rf"^{module}:6: in update: TypeError: update\(\) must return"):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))
        agent = ControllerSpec.from_json(json.dumps(self.spec(module, "NotFinite", {}))).make_agent(0)
        with self.assertRaisesRegex(ControllerFault, rf"^{module}:11: in update: ValueError: update\(\) must return "
                                                     r"finite numbers, got v=0.1, w=nan"):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))
        text = json.dumps(self.spec(module, "BadSetup", {}))
        agent = ControllerSpec.from_json(text).make_agent(0)
        self.assertEqual(str(agent.fault), f"{module}:17: in setup: RuntimeError: no goal for robot 0")
        with self.assertRaisesRegex(ConfigError, "robot 0's BadSetup failed to set up"):
            check(text)
        no_update = self.module("no_update.py", "from dream import Robot\n\n\nclass Ring(Robot):\n"
                                               "    def updat(self, step):\n        return (0.0, 0.0)\n")
        with self.assertRaises(ConfigError) as caught:
            check(json.dumps(self.spec(no_update, "Ring", {})))
        self.assertEqual(str(caught.exception), f"run.yaml:20: controller: robot 0's Ring failed to set up: "
                                                f"{no_update}: Ring has no update(self, step) method, the control "
                                                f"law returning (v, w); its methods: updat")


class BaseExceptionFaultTest(SpecFixture):
    """SystemExit and other BaseExceptions a controller raises fail that controller, as any
    exception does; only an interrupt of the whole run passes through."""

    SOURCE = """
        import sys

        import dream
        from dream import Robot


        class Raises(Robot):
            KEYS = {"what": dream.key("exit", kind="string")}

            def setup(self):
                if self.config["what"] == "exit_in_setup":
                    sys.exit("no setup")

            def update(self, step):
                what = self.config["what"]
                if what == "exit":
                    sys.exit(3)
                if what == "keyboard":
                    raise KeyboardInterrupt
                if what == "timeout":
                    raise dream.ControllerTimeout("still running")
                if what == "interrupt":
                    raise dream.RunInterrupted("interrupted")
                return (0.0, 0.0)
        """

    def agent(self, what):
        module = self.module("raises.py", self.SOURCE)
        spec = self.spec(module, "Raises", {"what": (what, 23)})
        return module, ControllerSpec.from_json(json.dumps(spec)).make_agent(0)

    def test_system_exit_in_update_is_a_fault_naming_the_line(self):
        module, agent = self.agent("exit")
        for step in (1, 2):  # the fault stays
            with self.assertRaises(ControllerFault) as caught:
                agent.step(world(step, [[0, 0, 0], [1, 0, 0]]))
            self.assertEqual(str(caught.exception), f"{module}:18: in update: SystemExit: 3")

    def test_system_exit_in_setup_is_a_setup_fault(self):
        module, agent = self.agent("exit_in_setup")
        self.assertEqual(str(agent.fault), f"{module}:13: in setup: SystemExit: no setup")
        with self.assertRaises(ControllerFault):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))

    def test_system_exit_while_loading_the_module_is_a_config_error(self):
        module = self.module("exits_on_import.py", """
            import sys
            sys.exit(2)
            """)
        with self.assertRaisesRegex(ConfigError, rf"cannot load {module}: {module}:3: in <module>: SystemExit: 2"):
            ControllerSpec.from_json(json.dumps(self.spec(module, "Nope", {})))

    def test_a_watchdog_timeout_is_a_fault(self):
        module, agent = self.agent("timeout")
        with self.assertRaisesRegex(ControllerFault, rf"^{module}:22: in update: ControllerTimeout: still running$"):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))

    def test_an_interrupt_of_the_run_passes_through_and_is_no_fault(self):
        module, agent = self.agent("interrupt")
        with self.assertRaises(dream.RunInterrupted):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))
        self.assertIsNone(agent.fault)

    def test_keyboard_interrupt_ends_the_run_only_where_ctrl_c_raises_it(self):
        import signal
        previous = signal.getsignal(signal.SIGINT)
        self.addCleanup(signal.signal, signal.SIGINT, previous)
        # A plain script (a submission): Ctrl-C is Python's KeyboardInterrupt, which ends the run.
        signal.signal(signal.SIGINT, signal.default_int_handler)
        module, agent = self.agent("keyboard")
        with self.assertRaises(KeyboardInterrupt):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))
        self.assertIsNone(agent.fault)
        # Embedded in dream run / dream agent, Python handles no signal: the controller raised it.
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        module, agent = self.agent("keyboard")
        with self.assertRaisesRegex(ControllerFault, rf"^{module}:20: in update: KeyboardInterrupt: $"):
            agent.step(world(1, [[0, 0, 0], [1, 0, 0]]))


class SeedingTest(SpecFixture):
    def test_sensor_noise_and_mailbox_seeds_as_the_controller_factory(self):
        module = self.module("idle.py", """
            from dream import Robot


            class Idle(Robot):
                def update(self, step):
                    return (0.0, 0.0)
            """)
        sensors = [{"kind": "movement", "period_steps": [1, 1], "range_m": 1.0, "direction_rad": 0.0,
                    "field_of_view_rad": 6.283185307179586, "noise_std": 0.0},
                   {"kind": "odometry", "period_steps": [1, 1], "noise_std": 0.01}]
        radio = {"kind": "graph", "period_steps": [1, 1], "range_m": 1.0, "graph": [[0, 1], [1, 0]], "leaders": [],
                 "loss_probability": 0.3, "delay_steps": 1}
        agent = ControllerSpec.from_json(json.dumps(self.spec(module, "Idle", {}, sensors=sensors, radio=radio,
                                                              seed=7))).make_agent(1)
        snapshot = world(1, [[0, 0, 0], [0.5, 0.5, 0.5]])
        agent.step(snapshot)
        expected = OdometrySensor(noise_std=0.01, seed=mix_seed(7, 1, 2))
        reference = recorder(robot_id=1)
        expected.sense(snapshot, reference)
        np.testing.assert_array_equal(agent.robot.pose, reference.pose)
        self.assertEqual(agent.mailbox.seed, mix_seed(7, 1, 0))
        self.assertEqual((agent.mailbox.loss_probability, agent.mailbox.delay_steps), (0.3, 1))


class GoToGoalExampleTest(SpecFixture):
    def test_reaches_every_goal(self):
        goals = [[0.416, 0.134], [-0.172, 0.323], [0.172, -0.323]]
        poses = np.array([[1.109, 0.287, 1.963], [-0.459, 0.693, -2.749], [0.459, -0.693, 0.393]])
        spec = ControllerSpec.from_json(json.dumps(self.spec(GO_TO_GOAL, "GoToGoal", {
            "goals": (goals, 30), "tolerance_m": (0.02, 29)}, robots=3)))
        agents = [spec.make_agent(i) for i in range(3)]
        velocities = np.zeros((3, 2))
        for step in range(1500):
            outputs = [agent.step(WorldSnapshot(step, poses, velocities)) for agent in agents]
            if all(output.done for output in outputs):
                break
            velocities = np.array([[output.v, output.w] for output in outputs])
            poses = poses + STEP_S * np.column_stack((velocities[:, 0] * np.cos(poses[:, 2]),
                                                      velocities[:, 0] * np.sin(poses[:, 2]), velocities[:, 1]))
        self.assertTrue(all(output.done for output in outputs), f"not all done by step {step}")
        np.testing.assert_array_less(np.linalg.norm(poses[:, :2] - np.array(goals), axis=1), 0.02 + 1e-12)
        self.assertLess(step, 1500)


if __name__ == "__main__":
    unittest.main()
