#!/usr/bin/python3
"""The script's side of `dream run SCRIPT.py` (python/rps_dream/rps/_world_link.py) on an in-memory
bus: a step of the world's is answered with one DREAM_CMD_<id> per robot whose bytes are lcm-gen's
velocity_command_t encoding of that step's command (the link packs them itself, for speed), and a
resent step gets the same bytes again.

Needs lcm-gen's Python types (DREAM_BUILD_DIR/python); exit 77 (skipped) without them or numpy.
"""

import os
import sys
import unittest

from unit_setup import SOURCE_DIR, require_numpy, types_dir

require_numpy()
import numpy as np  # noqa: E402
TYPES_DIR = types_dir("robot_poses_t")
os.environ["DREAM_PYTHON_TYPES_DIR"] = TYPES_DIR
os.environ["DREAM_BRIDGE_PYTHON_DIR"] = os.path.join(SOURCE_DIR, "bridge", "python")
sys.path.insert(0, os.path.join(SOURCE_DIR, "python", "rps_dream"))

from rps._world_link import WorldGone, WorldLink, _types  # noqa: E402


class WorldLinkTest(unittest.TestCase):
    def setUp(self):
        self.poses_t, self.command_t, _, self.status_t = _types()
        self.link = WorldLink(3, url="memq://")
        self.heard = []
        self.link.bus.subscribe("DREAM_CMD_.*", lambda channel, data: self.heard.append((channel, data)))

    def tearDown(self):
        self.link.close()

    def encode_step(self, step, robots=3, theta=(0.0, 1.0, -2.0)):
        message = self.poses_t()
        message.utime, message.step, message.run_id, message.num_robots = 33000 * step, step, 77, robots
        message.x, message.y = [0.1, 0.2, 0.3][:robots], [0.0, -0.1, 0.5][:robots]
        message.theta, message.v, message.w = list(theta)[:robots], [0.0] * robots, [0.0] * robots
        return message.encode()

    def publish_step(self, step, **kwargs):
        self.link.bus.publish("DREAM_POSES", self.encode_step(step, **kwargs))

    def publish_status(self, step, state):
        status = self.status_t()
        status.step, status.run_id, status.state, status.num_robots, status.detail = step, 77, state, 3, "the end"
        self.link.bus.publish("DREAM_STATUS", status.encode())

    def deliver(self):
        while self.link.bus.handle_timeout(0) > 0:
            pass

    def expected(self, step, i, v, w, done):
        command = self.command_t()
        command.utime, command.step, command.run_id, command.robot_id = 33000 * step, step, 77, i
        command.agent_id, command.v, command.w, command.done = self.link.agent_id, v, w, done
        return command.encode()

    def test_each_robots_command_is_lcm_gens_encoding(self):
        self.publish_step(4)
        np.testing.assert_array_equal(self.link.next_poses()[2], [0.0, 1.0, -2.0])
        velocities = np.array([[0.1, -0.2, np.nan], [1.5, 0.0, -3.0]])
        self.link.send(velocities, done=True)
        self.deliver()
        self.assertEqual([channel for channel, _ in self.heard], ["DREAM_CMD_0", "DREAM_CMD_1", "DREAM_CMD_2"])
        for i, (_, data) in enumerate(self.heard):
            self.assertEqual(data, self.expected(4, i, velocities[0, i], velocities[1, i], True))
        decoded = self.command_t.decode(self.heard[2][1])
        self.assertTrue(np.isnan(decoded.v))
        self.assertEqual((decoded.w, decoded.done), (-3.0, True))

    def test_a_resent_step_gets_the_same_bytes(self):
        self.publish_step(9)
        self.link.next_poses()
        self.link.send(np.array([[0.05, 0.0, 0.2], [0.0, 0.4, 0.0]]))
        self.deliver()
        first = list(self.heard)
        self.publish_step(9)  # the world resends the step it waits on
        self.deliver()
        self.assertEqual(self.heard[3:], first)
        self.assertEqual(first[1][1], self.expected(9, 1, 0.0, 0.4, False))

    def test_foreign_and_forged_steps_are_not_handed_out_and_an_ending_status_ends(self):
        self.publish_step(1)
        np.testing.assert_array_equal(self.link.next_poses()[0], [0.1, 0.2, 0.3])
        self.link.send(np.zeros((2, 3)))
        self.publish_step(2, robots=2)  # another world's, with two robots
        self.publish_step(2, theta=(0.0, float("nan"), 0.0))
        forged = bytearray(self.encode_step(2))
        forged[0] ^= 0xFF  # not robot_poses_t's fingerprint
        self.link.bus.publish("DREAM_POSES", bytes(forged))
        self.link.bus.publish("DREAM_POSES", b"\x00" * 20)
        self.publish_status(2, 1)  # running: not an end
        self.deliver()
        self.assertIsNone(self.link._fresh)
        self.assertFalse(self.link.ended)
        self.publish_status(2, 2)  # finished
        with self.assertRaisesRegex(WorldGone, "the end"):
            self.link.next_poses()


if __name__ == "__main__":
    unittest.main()
