#!/usr/bin/python3
"""Unit tests of drawing in the Python runtime (python/dream/drawing.py, Robot.draw_*, the agent
host's DREAM_DRAW_<id>): shapes in world coordinates, the bounds (drawing_t's: clipped with a
counted reason), the message (lcm-gen's drawing_t, as the world checks it), sent only when the
drawing changed, again with a resent step, never touching the command.

Needs lcm-gen's Python types (DREAM_BUILD_DIR/python); exit 77 (skipped) without them or numpy.
"""

import math
import os
import re
import unittest

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_numpy, types_dir

require_numpy()
import numpy as np  # noqa: E402
TYPES_DIR = types_dir("drawing_t")
put_runtime_on_path()

import dream  # noqa: E402
from dream import Robot, RobotAgent  # noqa: E402
from dream import drawing as drawing_module  # noqa: E402
from dream.drawing import Drawing, rgba_of  # noqa: E402
from dream.embedded import setup  # noqa: E402

setup(TYPES_DIR, 50)  # lcm-gen's types as dream.<type>; log only above ERROR
from dream.agent_host import AgentHost  # noqa: E402

RUN = 0x7e57


class MemoryBus:
    url = "memory://"

    def __init__(self):
        self.handler = None
        self.published = []

    def subscribe(self, regex, handler):
        self.handler = handler

    def publish(self, channel, data):
        self.published.append((channel, bytes(data)))

    def take(self):
        published, self.published = self.published, []
        return published


class Painter(Robot):
    """Drives at 0.05 m/s; draws its own circle and a label at every update; from step 3 on the
    same thing each step (so nothing new is sent); `plain` robots draw nothing."""

    plain = False

    def update(self, step):
        if not self.plain:
            label = min(step, 3)
            self.draw_circle([0.1 * self.id, 0.0], 0.2, color="red", fill=True, alpha=0.5)
            self.draw_arrow([0.0, 0.0], [0.3, 0.1], color=(0.0, 0.0, 1.0))
            self.draw_text([0.0, -0.5], f"robot {self.id} step {label}", height=0.05)
        return (0.05, 0.0)


def poses(step, n=2):
    message = dream.robot_poses_t()
    message.utime, message.step, message.run_id, message.num_robots = step * 33000, step, RUN, n
    message.x = [0.1 * i for i in range(n)]
    message.y, message.theta, message.v, message.w = [0.0] * n, [0.0] * n, [0.0] * n, [0.0] * n
    return message.encode()


class DrawingBoundsTest(unittest.TestCase):
    def test_the_bounds_are_drawing_ts(self):
        with open(os.path.join(SOURCE_DIR, "lcmtypes", "dream", "drawing_t.lcm"), encoding="utf-8") as f:
            lcm = f.read()
        for name in ("MAX_SHAPES", "MAX_POLYGON_POINTS", "MAX_POINTS", "MAX_TEXT_BYTES", "MAX_ALL_TEXT_BYTES"):
            declared = re.search(name + r"\s*=\s*(\d+)", lcm)
            self.assertIsNotNone(declared, name)
            self.assertEqual(getattr(drawing_module, name), int(declared.group(1)), name)
        for name, value in (("LINE", 1), ("CIRCLE", 2), ("POLYGON", 3), ("ARROW", 4), ("TEXT", 5)):
            self.assertEqual(getattr(drawing_module, name), getattr(dream.drawing_t, name), name)
            self.assertEqual(getattr(drawing_module, name), value)

    def test_shapes_past_the_bounds_are_clipped_and_counted_by_reason(self):
        d = Drawing()
        for k in range(70):
            d.line([0, 0], [k * 0.01, 1])
        self.assertEqual(len(d.shapes), 64)
        self.assertEqual(d.clipped, 6)
        self.assertEqual(d.clip_reasons, {"more than 64 shapes in one step (left out)": 6})

    def test_a_long_polygon_is_cut_and_a_short_one_left_out(self):
        d = Drawing()
        d.polygon([[math.cos(a), math.sin(a)] for a in np.linspace(0, 6, 100)])
        d.polygon([[0, 0], [1, 1]])
        self.assertEqual(len(d.shapes), 1)
        self.assertEqual(len(d.shapes[0].points), 64)
        self.assertEqual(d.clipped, 36 + 1)
        self.assertIn("polygon corners past 64 (cut)", d.clip_reasons)

    def test_text_is_cut_between_characters_and_made_printable(self):
        d = Drawing()
        d.text([0, 0], "\u00e9" * 60)  # 120 bytes
        d.text([0, 0], "a\nb\x00")
        self.assertEqual(d.shapes[0].text, "\u00e9" * 48)
        self.assertEqual(d.shapes[1].text, "a?b?")
        self.assertEqual(d.clipped, 24 + 2)

    def test_points_that_are_not_finite_or_far_away_leave_their_shape_out(self):
        d = Drawing()
        d.line([0, 0], [math.nan, 0])
        d.circle([1e6, 0], 0.1)
        d.circle([0, 0], -1)
        d.circle([0, 0], 0.1)
        self.assertEqual([s.kind for s in d.shapes], [drawing_module.CIRCLE])
        self.assertEqual(d.clipped, 3)

    def test_arguments_of_the_wrong_type_raise_naming_them(self):
        d = Drawing()
        with self.assertRaisesRegex(ValueError, "start 'a': expected a point"):
            d.line("a", [0, 0])
        with self.assertRaisesRegex(ValueError, "colour 'chartreuse'"):
            d.circle([0, 0], 0.1, color="chartreuse")
        with self.assertRaisesRegex(ValueError, "radius"):
            d.circle([0, 0], "big")

    def test_colours(self):
        self.assertEqual(rgba_of("#ff0000"), 0xFF0000FF)
        self.assertEqual(rgba_of("#11223344"), 0x11223344)
        self.assertEqual(rgba_of((0, 0, 1)), 0x0000FFFF)
        self.assertEqual(rgba_of("k", alpha=0.0), 0x00000000)


class DrawingHostTest(unittest.TestCase):
    def setUp(self):
        self.bus = MemoryBus()
        self.agents = [RobotAgent(Painter(i, dream.RobotParams(), {}, 2)) for i in range(2)]
        self.agents[1].robot.plain = True
        self.host = AgentHost(self.bus, self.agents, agent_id=77, num_robots=2)

    def test_a_drawing_goes_before_the_command_and_only_when_it_changed(self):
        self.host._on_message("DREAM_POSES", poses(1))
        first = self.bus.take()
        self.assertEqual([c for c, _ in first], ["DREAM_DRAW_0", "DREAM_CMD_0", "DREAM_CMD_1"])
        message = dream.drawing_t.decode(first[0][1])
        self.assertEqual((message.step, message.run_id, message.robot_id, message.agent_id), (1, RUN, 0, 77))
        self.assertEqual(list(message.kind), [drawing_module.CIRCLE, drawing_module.ARROW, drawing_module.TEXT])
        self.assertEqual(message.rgba[0] & 0xFFFFFFFF, 0xD6272880)
        self.assertEqual(list(message.point_count), [1, 2, 1])
        self.assertEqual(list(message.fill), [1, 0, 0])
        self.assertEqual(message.text.decode("utf-8"), "robot 0 step 1")
        self.assertEqual((message.num_points, message.num_text_bytes, message.clipped), (4, 14, 0))
        # A resent step: the same bytes again, the robot not run again.
        self.host._on_message("DREAM_POSES", poses(1))
        self.assertEqual(self.bus.take(), first)
        for step in (2, 3):
            self.host._on_message("DREAM_POSES", poses(step))
            self.assertEqual([c for c, _ in self.bus.take()], ["DREAM_DRAW_0", "DREAM_CMD_0", "DREAM_CMD_1"])
        self.host._on_message("DREAM_POSES", poses(4))  # drew what it drew at step 3: nothing to send
        self.assertEqual([c for c, _ in self.bus.take()], ["DREAM_CMD_0", "DREAM_CMD_1"])

    def test_drawing_changes_no_command(self):
        self.host._on_message("DREAM_POSES", poses(1))
        commands = {c: dream.velocity_command_t.decode(d) for c, d in self.bus.take() if c.startswith("DREAM_CMD")}
        self.assertEqual([(m.v, m.w) for m in commands.values()], [(0.05, 0.0), (0.05, 0.0)])

    def test_a_drawing_that_stops_is_cleared_once(self):
        self.host._on_message("DREAM_POSES", poses(1))
        self.bus.take()
        self.agents[0].robot.plain = True
        self.host._on_message("DREAM_POSES", poses(2))
        sent = self.bus.take()
        self.assertEqual([c for c, _ in sent], ["DREAM_DRAW_0", "DREAM_CMD_0", "DREAM_CMD_1"])
        self.assertEqual(dream.drawing_t.decode(sent[0][1]).num_shapes, 0)
        self.host._on_message("DREAM_POSES", poses(3))
        self.assertEqual([c for c, _ in self.bus.take()], ["DREAM_CMD_0", "DREAM_CMD_1"])


if __name__ == "__main__":
    unittest.main()
