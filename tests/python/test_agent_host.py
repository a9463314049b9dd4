#!/usr/bin/python3
"""Unit tests of the Python agent host (python/dream/agent_host.py) on an in-memory bus: the
lockstep contract of agents/agent_host's AgentHost, and hostile traffic (forged counts, non-finite
values, radio messages on the wrong channel, garbage) counted and dropped, never raised.

Needs lcm-gen's Python types (DREAM_BUILD_DIR/python); exit 77 (skipped) without them or numpy.
"""

import os
import re
import struct
import sys
import unittest

from unit_setup import put_runtime_on_path, require_numpy, types_dir

require_numpy()
TYPES_DIR = types_dir("robot_poses_t")
put_runtime_on_path()

import dream  # noqa: E402
from dream import Robot, RobotAgent, RangeRadio, pack_floats  # noqa: E402
from dream.embedded import setup  # noqa: E402

setup(TYPES_DIR, 50)  # lcm-gen's types as dream.<type>; log only above ERROR
from dream.agent_host import AgentHost  # noqa: E402


class MemoryBus:
    """A bus that keeps what is published and hands messages to the one subscriber."""

    url = "memory://"

    def __init__(self):
        self.handler = None
        self.published = []

    def subscribe(self, regex, handler):
        self.handler = handler

    def publish(self, channel, data):
        self.published.append((channel, bytes(data)))

    def deliver(self, channel, data):
        self.handler(channel, data)

    def take(self):
        published, self.published = self.published, []
        return published


class Counter(Robot):
    """Drives at 0.01 m/s times the number of updates so far; talks every step; robot 1 raises
    at step 3."""

    def setup(self):
        self.updates = 0

    def on_radio(self, heard):
        return pack_floats([self.id])

    def update(self, step):
        if self.id == 1 and step == 3:
            raise KeyError("no such goal")
        self.updates += 1
        return (0.01 * self.updates, 0.0)


RUN = 0x7e57
OTHER_RUN = 0x0bad


def poses(step, n=2, x=None, run_id=RUN):
    message = dream.robot_poses_t()
    message.utime, message.step, message.run_id, message.num_robots = step * 33000, step, run_id, n
    message.x = x if x is not None else [0.1 * i for i in range(n)]
    message.y, message.theta, message.v, message.w = [0.0] * n, [0.0] * n, [0.0] * n, [0.0] * n
    return message.encode()


class AgentHostTest(unittest.TestCase):
    def setUp(self):
        self.bus = MemoryBus()
        agents = [RobotAgent(Counter(i, dream.RobotParams(), {}, 2), radio=RangeRadio(1.0)) for i in range(2)]
        self.host = AgentHost(self.bus, agents, agent_id=77, num_robots=2)
        self.agents = agents

    def commands(self, published):
        return {channel: dream.velocity_command_t.decode(data) for channel, data in published
                if channel.startswith("DREAM_CMD_")}

    def test_each_step_is_answered_with_radio_then_command(self):
        self.bus.deliver("DREAM_POSES", poses(1))
        published = self.bus.take()
        self.assertEqual([channel for channel, _ in published],
                         ["DREAM_RADIO_0", "DREAM_CMD_0", "DREAM_RADIO_1", "DREAM_CMD_1"])
        command = self.commands(published)["DREAM_CMD_0"]
        self.assertEqual((command.step, command.robot_id, command.agent_id, command.v), (1, 0, 77, 0.01))

    def test_a_resent_step_gets_the_same_bytes_without_running_the_robot_again(self):
        self.bus.deliver("DREAM_POSES", poses(1))
        first = self.bus.take()
        self.bus.deliver("DREAM_POSES", poses(1))
        self.assertEqual(self.bus.take(), first)
        self.assertEqual(self.agents[0].robot.updates, 1)
        self.bus.deliver("DREAM_POSES", poses(2))
        self.bus.take()
        self.bus.deliver("DREAM_POSES", poses(1))  # a late duplicate of the step before
        self.assertEqual(self.bus.take(), [])

    def test_forged_and_broken_messages_are_counted_and_dropped(self):
        huge = bytearray(poses(1))
        struct.pack_into(">i", huge, 8 + 24, 1 << 28)  # num_robots 2^28 in a 100-byte datagram
        self.bus.deliver("DREAM_POSES", bytes(huge))
        negative = bytearray(poses(1))
        struct.pack_into(">i", negative, 8 + 24, -5)
        self.bus.deliver("DREAM_POSES", bytes(negative))
        self.bus.deliver("DREAM_POSES", poses(1, x=[float("nan"), 0.0]))
        self.bus.deliver("DREAM_POSES", b"\x00" * 3)
        self.bus.deliver("DREAM_OBSTACLES", b"garbage")
        self.assertEqual(self.bus.take(), [])
        self.assertEqual(self.host.bad_messages, {"DREAM_POSES": 4, "DREAM_OBSTACLES": 1})
        self.bus.deliver("DREAM_POSES", poses(1))  # the run goes on
        self.assertEqual(len(self.commands(self.bus.take())), 2)
        radio = dream.radio_message_t()
        radio.run_id, radio.sender_id, radio.payload, radio.payload_size = RUN, 5, b"\x01", 1
        self.bus.deliver("DREAM_RADIO_4", radio.encode())  # sender 5 on robot 4's channel
        radio.sender_id = 999999
        self.bus.deliver("DREAM_RADIO_999999", radio.encode())  # no such robot in this run
        self.assertEqual(self.host.bad_messages["DREAM_RADIO_4"], 1)
        self.assertEqual(self.host.bad_messages["DREAM_RADIO_999999"], 1)
        self.assertEqual([len(agent.mailbox._by_sender) for agent in self.agents], [0, 0])  # nothing stored

    def test_the_host_follows_the_run_it_joined_and_only_its_next_steps(self):
        self.bus.deliver("DREAM_POSES", poses(1))
        self.bus.take()
        self.bus.deliver("DREAM_POSES", poses(2, run_id=OTHER_RUN))  # a second world on the URL
        self.bus.deliver("DREAM_POSES", poses(1 << 40))               # a forged step far ahead
        self.bus.deliver("DREAM_POSES", poses(0))                     # or behind
        self.assertEqual(self.bus.take(), [])
        self.assertEqual(self.host.follower.other_runs, {OTHER_RUN})
        self.bus.deliver("DREAM_POSES", poses(2))  # the world's next step is still answered
        self.assertEqual([c.step for c in self.commands(self.bus.take()).values()], [2, 2])
        self.assertEqual(self.agents[0].robot.updates, 2)
        finished = dream.run_status_t()
        finished.run_id, finished.step, finished.state, finished.detail = OTHER_RUN, 2, 2, "forged"
        self.bus.deliver("DREAM_STATUS", finished.encode())
        self.assertFalse(self.host.world_finished)  # another run's FINISHED does not end ours
        finished.run_id = RUN
        self.bus.deliver("DREAM_STATUS", finished.encode())
        self.assertTrue(self.host.world_finished)

    def test_a_far_jump_is_followed_once_the_next_step_confirms_it(self):
        self.bus.deliver("DREAM_POSES", poses(1))
        self.bus.deliver("DREAM_POSES", poses(500))
        self.bus.take()
        self.assertEqual(self.agents[0].robot.updates, 1)
        self.bus.deliver("DREAM_POSES", poses(501))
        self.assertEqual([c.step for c in self.commands(self.bus.take()).values()], [501, 501])

    def test_radio_from_the_future_or_another_run_is_dropped(self):
        self.bus.deliver("DREAM_POSES", poses(1))
        self.bus.take()
        radio = dream.radio_message_t()
        radio.run_id, radio.step, radio.sender_id, radio.payload, radio.payload_size = RUN, 1 << 40, 1, b"\x01", 1
        self.bus.deliver("DREAM_RADIO_1", radio.encode())
        radio.step, radio.run_id = 1, OTHER_RUN
        self.bus.deliver("DREAM_RADIO_1", radio.encode())
        self.assertEqual(self.host.bad_messages["DREAM_RADIO_1"], 2)
        self.assertEqual([len(agent.mailbox._by_sender) for agent in self.agents], [0, 0])

    def test_a_world_of_another_robot_count_is_never_joined(self):
        # Agents started with another experiment's config would drive its robots.
        self.bus.deliver("DREAM_POSES", poses(1, n=1))
        self.bus.deliver("DREAM_POSES", poses(1, n=3))
        self.assertEqual(list(self.commands(self.bus.take())), [])
        self.assertEqual(self.host.bad_messages, {"DREAM_POSES": 2})
        self.assertFalse(self.host.follower.joined)
        self.assertIn("came from a world of 3 robots, but this agent's config has 2",
                      self.host.silence_text(5, "memq://"))
        self.bus.deliver("DREAM_POSES", poses(2))  # its own world is joined as ever
        self.assertEqual(sorted(self.commands(self.bus.take())), ["DREAM_CMD_0", "DREAM_CMD_1"])
        self.assertIn("no DREAM_POSES for 5 s", AgentHost(MemoryBus(), [], 1, 2).silence_text(5, "memq://"))

    def test_a_raising_controller_is_reported_once_and_its_robot_no_longer_answered(self):
        for step in (1, 2, 3, 4):
            self.bus.deliver("DREAM_POSES", poses(step))
        published = self.bus.take()
        faults = [dream.robot_fault_t.decode(data) for channel, data in published if channel == "DREAM_FAULT_1"]
        self.assertEqual(len(faults), 1)
        self.assertEqual((faults[0].step, faults[0].robot_id, faults[0].agent_id), (3, 1, 77))
        self.assertRegex(faults[0].detail, r"test_agent_host\.py:\d+: in update: KeyError: 'no such goal'")
        steps_of = lambda channel: [dream.velocity_command_t.decode(d).step for c, d in published if c == channel]
        self.assertEqual(steps_of("DREAM_CMD_0"), [1, 2, 3, 4])
        self.assertEqual(steps_of("DREAM_CMD_1"), [1, 2])
        self.assertEqual(list(self.host.faults()), [1])

    def host_of(self, robot_class):
        bus = MemoryBus()
        agents = [RobotAgent(robot_class(i, dream.RobotParams(), {}, 2)) for i in range(2)]
        return bus, AgentHost(bus, agents, agent_id=77, num_robots=2)

    def test_a_controller_that_exits_is_reported_like_any_fault(self):
        class Exits(Robot):
            def update(self, step):
                if self.id == 0 and step == 2:
                    sys.exit(3)  # no "Exception ignored on calling ctypes callback", no silent agent
                return (0.01, 0.0)

        bus, host = self.host_of(Exits)
        for step in (1, 2, 3):
            bus.deliver("DREAM_POSES", poses(step))  # nothing may escape to LCM's C code
        published = bus.take()
        faults = [dream.robot_fault_t.decode(data) for channel, data in published if channel == "DREAM_FAULT_0"]
        self.assertEqual(len(faults), 1)
        self.assertEqual((faults[0].step, faults[0].robot_id), (2, 0))
        self.assertRegex(faults[0].detail, r"test_agent_host\.py:\d+: in update: SystemExit: 3$")
        steps_of = lambda channel: [dream.velocity_command_t.decode(d).step for c, d in published if c == channel]
        self.assertEqual(steps_of("DREAM_CMD_0"), [1])
        self.assertEqual(steps_of("DREAM_CMD_1"), [1, 2, 3])

    def test_a_controller_stopped_by_the_watchdog_fails_alone(self):
        class Stuck(Robot):
            def update(self, step):
                if self.id == 0 and step == 2:
                    raise dream.ControllerTimeout("still running after 0.8 s")  # as the watchdog raises it
                return (0.01, 0.0)

        bus, host = self.host_of(Stuck)
        for step in (1, 2, 3):
            bus.deliver("DREAM_POSES", poses(step))
        published = bus.take()
        faults = [dream.robot_fault_t.decode(data) for channel, data in published if channel == "DREAM_FAULT_0"]
        self.assertEqual([fault.step for fault in faults], [2])
        self.assertRegex(faults[0].detail, r"in update: ControllerTimeout: still running after 0\.8 s$")
        self.assertEqual(list(host.faults()), [0])

    def test_a_timeout_raised_again_while_the_fault_is_written_still_fails_the_robot(self):
        # The watchdog raises ControllerTimeout again every 0.25 s while the call runs; one that
        # lands while the first one's text is made (a deep traceback) used to escape the host:
        # no fault, the robot silent until the world gave up on it.
        class Slow(Robot):
            def update(self, step):
                if self.id == 0 and step == 2:
                    raise dream.ControllerTimeout("still running after 0.8 s")
                return (0.01, 0.0)

        def raises_again(exc, user_file=None):
            raise dream.ControllerTimeout("still running after 0.8 s")

        original = dream.robot_agent.controller_error_text
        dream.robot_agent.controller_error_text = raises_again
        self.addCleanup(setattr, dream.robot_agent, "controller_error_text", original)
        bus, host = self.host_of(Slow)
        for step in (1, 2, 3):
            bus.deliver("DREAM_POSES", poses(step))
        published = bus.take()
        faults = [dream.robot_fault_t.decode(data) for channel, data in published if channel == "DREAM_FAULT_0"]
        self.assertEqual([fault.step for fault in faults], [2])
        self.assertRegex(faults[0].detail, r"^ControllerTimeout: still running after 0\.8 s \(raised again while")
        steps_of = lambda channel: [dream.velocity_command_t.decode(d).step for c, d in published if c == channel]
        self.assertEqual(steps_of("DREAM_CMD_1"), [1, 2, 3])  # the other robot goes on

    def test_an_interrupt_of_the_run_stops_every_answer_and_blames_no_controller(self):
        class Interrupted(Robot):
            def update(self, step):
                if self.id == 0 and step == 2:
                    raise dream.RunInterrupted("interrupted (Ctrl-C or SIGTERM)")  # as the watchdog raises it
                return (0.01, 0.0)

        bus, host = self.host_of(Interrupted)
        for step in (1, 2, 3):
            bus.deliver("DREAM_POSES", poses(step))
        published = bus.take()
        self.assertTrue(host.interrupted)
        self.assertEqual(host.faults(), {})
        self.assertEqual([c for c, _ in published if c.startswith("DREAM_FAULT_")], [])
        steps_of = lambda channel: [dream.velocity_command_t.decode(d).step for c, d in published if c == channel]
        self.assertEqual(steps_of("DREAM_CMD_0"), [1])
        self.assertEqual(steps_of("DREAM_CMD_1"), [1])  # the step's handling ended at once

    def test_each_controller_call_is_marked_for_the_watchdog(self):
        cell = memoryview(bytearray(24)).cast("q")  # token, robot, step: dream times the call by them too
        seen = []
        marked = []

        class Marks(Robot):
            def update(self, step):
                seen.append(cell[0])
                marked.append((cell[1], cell[2]))
                if self.id == 1:
                    raise KeyError("fails")
                return (0.0, 0.0)

        previous = dream.agent_host.call_cell()
        dream.agent_host.set_call_cell(cell)
        self.addCleanup(dream.agent_host.set_call_cell, previous)
        bus, host = self.host_of(Marks)
        bus.deliver("DREAM_POSES", poses(1))
        self.assertEqual(len(seen), 2)
        self.assertTrue(all(token > 0 for token in seen), seen)
        self.assertNotEqual(seen[0], seen[1])  # a token per call
        self.assertEqual(marked, [(0, 1), (1, 1)])  # which robot's call, at which step
        self.assertEqual(cell[0], 0)  # cleared after each call, a failing one too

    def test_nothing_a_handler_raises_reaches_lcms_c_code(self):
        # A deep recursion made the host's own handler raise again while it handled the error:
        # ctypes printed "Exception ignored on calling ctypes callback" and dropped it, and the
        # host never reported the robot. dream.lcm's callback keeps everything and logs it.
        from dream.lcm import Lcm
        bus = Lcm("memq://")
        self.addCleanup(bus.close)

        def handler(channel, data):
            raise RecursionError("maximum recursion depth exceeded")

        bus.subscribe("DREAM_TEST", handler)
        unraised = []
        previous = sys.unraisablehook
        sys.unraisablehook = unraised.append
        self.addCleanup(setattr, sys, "unraisablehook", previous)
        bus.publish("DREAM_TEST", b"x")
        with self.assertLogs("dream", level="ERROR") as logged:
            self.assertGreater(bus.handle_timeout(1000), 0)
        self.assertEqual(unraised, [])
        self.assertIn("DREAM_TEST: a message handler failed: RecursionError", logged.output[0])

    def test_a_sim_only_run_of_100_robots_is_hosted_and_129_are_refused(self):
        # The config holds a run to 50 robots unless it is sim_only (up to the bus's 128);
        # the host bounds what it decodes by the bus alone.
        bus = MemoryBus()
        agents = [RobotAgent(Counter(i, dream.RobotParams(), {}, 100)) for i in range(100)]
        host = AgentHost(bus, agents, agent_id=5, num_robots=100)
        bus.deliver("DREAM_POSES", poses(1, n=100))
        commands = self.commands(bus.take())
        self.assertEqual(sorted(commands), sorted(f"DREAM_CMD_{i}" for i in range(100)))
        self.assertEqual({c.step for c in commands.values()}, {1})
        self.assertEqual(host.bad_messages, {})
        bus.deliver("DREAM_POSES", poses(2, n=129))  # past the bus's bound: refused before it is decoded
        self.assertEqual(bus.take(), [])
        self.assertEqual(host.bad_messages, {"DREAM_POSES": 1})
        self.assertIsNone(host.other_world_robots)  # never read as a world of 129 robots
        status = dream.run_status_t()
        status.run_id, status.step, status.state, status.detail = RUN, 2, dream.run_status_t.FINISHED, "done"
        status.num_lost, status.lost_robot_ids = 129, list(range(129))
        bus.deliver("DREAM_STATUS", status.encode())
        self.assertEqual(host.bad_messages, {"DREAM_POSES": 1, "DREAM_STATUS": 1})
        self.assertFalse(host.world_finished)

    def message_limit(self, name):
        """lcm::MessageLimits' `name`, read from its header (the Python runtime stands alone)."""
        header = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "lcmtypes", "lcm", "include",
                              "dream", "lcm", "message_limits.h")
        with open(header, encoding="utf-8") as f:
            declared = re.search(name + r"\s*=\s*(\d+)", f.read())
        self.assertIsNotNone(declared, f"{name} in {header}")
        return int(declared.group(1))

    def test_the_robot_limit_is_the_buses(self):
        self.assertEqual(dream.agent_host.MAX_ROBOTS, self.message_limit("kRobots"))

    def test_the_detail_limit_is_the_worlds(self):
        self.assertEqual(dream.agent_host.MAX_DETAIL_BYTES, self.message_limit("kDetailBytes"))

    def test_a_fault_text_is_sent_as_the_world_accepts_it(self):
        # UTF-8 without NUL, at most MAX_DETAIL_BYTES, cut between characters: the
        # world refuses anything else (lcmtypes' WireLayout), and the fault would be lost.
        wire = AgentHost._wire_text
        self.assertEqual(wire("caf\u00e9 \U0001F916"), "caf\u00e9 \U0001F916")
        self.assertEqual(wire("a\x00b"), "a\\0b")  # as the C++ host's WireText::Of writes it
        self.assertEqual(wire("path \udcff"), "path ?")  # a surrogate-escaped byte of a file name
        long_text = "\u00e9" * dream.agent_host.MAX_DETAIL_BYTES  # two bytes each
        cut = wire(long_text)
        self.assertEqual(cut, "\u00e9" * (dream.agent_host.MAX_DETAIL_BYTES // 2))
        self.assertEqual(wire("x" + long_text).encode("utf-8"), ("x" + "\u00e9" * (dream.agent_host.MAX_DETAIL_BYTES // 2 - 1)).encode("utf-8"))

    def test_the_world_ending_the_run_is_noticed(self):
        self.bus.deliver("DREAM_POSES", poses(1))
        status = dream.run_status_t()
        status.run_id, status.step = RUN, 1
        status.state, status.detail = dream.run_status_t.FINISHED, "every robot reported done"
        self.bus.deliver("DREAM_STATUS", status.encode())
        self.assertTrue(self.host.world_finished)
        self.assertEqual(self.host.end_detail, "every robot reported done")


if __name__ == "__main__":
    unittest.main()
