#!/usr/bin/python3
"""The script's side of `dream run SCRIPT.py` (python/rps_dream/rps/_world_link.py) on an in-memory
bus: a step of the world's is answered with one DREAM_CMDS message whose bytes are lcm-gen's
robot_commands_t encoding of that step's commands (the link packs them itself, for speed), and a
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
        self.poses_t, self.commands_t, _, self.status_t = _types()
        self.link = WorldLink(3, url="memq://")
        self.heard = []
        self.link.bus.subscribe("DREAM_CMD.*", lambda channel, data: self.heard.append((channel, data)))

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

    def expected(self, step, velocities, done):
        commands = self.commands_t()
        commands.utime, commands.step, commands.run_id = 33000 * step, step, 77
        commands.agent_id, commands.num_commands = self.link.agent_id, velocities.shape[1]
        commands.robot_id = list(range(velocities.shape[1]))
        commands.v, commands.w = velocities[0].tolist(), velocities[1].tolist()
        commands.done = [done] * velocities.shape[1]
        return commands.encode()

    def test_every_robots_command_is_one_message_in_lcm_gens_encoding(self):
        self.publish_step(4)
        np.testing.assert_array_equal(self.link.next_poses()[2], [0.0, 1.0, -2.0])
        velocities = np.array([[0.1, -0.2, np.nan], [1.5, 0.0, -3.0]])
        self.link.send(velocities, done=True)
        self.deliver()
        self.assertEqual([channel for channel, _ in self.heard], ["DREAM_CMDS"])
        self.assertEqual(self.heard[0][1], self.expected(4, velocities, True))
        decoded = self.commands_t.decode(self.heard[0][1])
        self.assertEqual(list(decoded.robot_id), [0, 1, 2])
        self.assertTrue(np.isnan(decoded.v[2]))
        self.assertEqual((decoded.w[2], list(decoded.done)), (-3.0, [True, True, True]))

    def test_a_wider_velocity_array_sends_the_links_robots_only(self):
        self.publish_step(5)
        self.link.next_poses()
        velocities = np.arange(8.0).reshape(2, 4) / 10
        self.link.send(velocities)
        self.deliver()
        self.assertEqual(self.heard[0][1], self.expected(5, velocities[:, :3], False))

    def test_a_resent_step_gets_the_same_bytes(self):
        self.publish_step(9)
        self.link.next_poses()
        self.link.send(np.array([[0.05, 0.0, 0.2], [0.0, 0.4, 0.0]]))
        self.deliver()
        first = list(self.heard)
        self.publish_step(9)  # the world resends the step it waits on
        self.deliver()
        self.assertEqual(len(first), 1)
        self.assertEqual(self.heard[1:], first)
        self.assertEqual(first[0][1], self.expected(9, np.array([[0.05, 0.0, 0.2], [0.0, 0.4, 0.0]]), False))

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
