#!/usr/bin/python3
"""drawing_run: what a controller draws travels on DREAM_DRAW_<id>, is logged, rendered, and never
changes the run (issue 37 item 4).

A three-robot Python controller that drives to its goals and, with `controller.draw: true`, draws
each update: a line to its goal, a circle round it, a heading arrow, its id and step as text and
(robot 0) a filled green square in a corner of the arena no robot drives through.

1. The run with drawing and the same run without: every step's poses equal, the same summary
   metrics and verdict, `dream log diff` of every channel but DREAM_DRAW_<id> equal (and of the
   whole logs different, naming DREAM_DRAW_0); the drawing run's log holds DREAM_DRAW_<id> of every robot, each a
   drawing_t of that robot and run, with the shapes drawn (kinds, text); the other holds none.
2. `dream render` of each as a PNG: the drawing run's picture has the green square (pixels of its
   colour where it was drawn), the other has none, nor has the drawing run's with --no-drawings;
   the last frame of a GIF video of the drawing run has it too.
3. `dream log echo` shows a DREAM_DRAW_0 message as JSON, its text readable.

Usage: drawing_run.py --dream BIN --source DIR --types-dir DIR
"""

import json
import os
import subprocess

from dreamtest import argument_parser, check, import_types, main, read_events, read_summary

STEPS = 90
CONTROLLER = '''
import math

from dream import Robot, SingleIntegratorToUnicycle, key


class Painter(Robot):
    KEYS = {"goals": key(kind="points", per_robot=True), "draw": key(False, kind="bool")}

    def setup(self):
        self.goal = self.config["goals"][self.id].tolist()
        self.si_to_uni = SingleIntegratorToUnicycle()

    def update(self, step):
        x, y, theta = self.pose.tolist()
        if self.config["draw"]:
            self.draw_line([x, y], self.goal, color="#1f77b4", width=0.01)
            self.draw_circle(self.goal, 0.06, color="red", width=0.01)
            self.draw_arrow([x, y], [x + 0.2 * math.cos(theta), y + 0.2 * math.sin(theta)], color="orange")
            self.draw_text([x + 0.08, y + 0.08], f"r{self.id} k={step}", height=0.06)
            if self.id == 0:
                self.draw_polygon([[1.1, -0.9], [1.5, -0.9], [1.5, -0.5], [1.1, -0.5]], color="#00c800", fill=True)
        dx, dy = 0.8 * (self.goal[0] - x), 0.8 * (self.goal[1] - y)
        speed = math.hypot(dx, dy)
        if speed > 0.15:
            dx, dy = dx * 0.15 / speed, dy * 0.15 / speed
        return self.limit_actuators(self.si_to_uni.map([dx, dy], theta))
'''
CONFIG = f"""name: drawing
seed: 1
robots: 3
steps: {STEPS}
stop_when_done: false
world:
  mode: lockstep
initial_poses:
  - [-1.0, 0.5, 0.0]
  - [-1.0, 0.0, 0.0]
  - [-1.0, -0.5, 0.0]
controller:
  kind: python
  module: painter.py
  class: Painter
  goals:
    - [0.0, 0.5]
    - [0.0, 0.0]
    - [0.0, -0.5]
"""
# The square's corners in pixels of a 1280 px picture are not assumed: its colour is looked for
# anywhere, and nothing else in a picture is this green.
GREEN = (0, 200, 0)


def green_pixels(path):
    from PIL import Image
    image = Image.open(path).convert("RGB")
    return sum(1 for r, g, b in image.getdata() if abs(r - GREEN[0]) < 40 and abs(g - GREEN[1]) < 40 and
               abs(b - GREEN[2]) < 40)


def poses_by_step(dream, log):
    poses = {}
    for event in read_events(log):
        if event.channel == "DREAM_POSES":
            p = dream.robot_poses_t.decode(event.data)
            poses[p.step] = (tuple(p.x), tuple(p.y), tuple(p.theta))
    return poses


def drawings_of(dream, log):
    found = []
    for event in read_events(log):
        if event.channel.startswith("DREAM_DRAW_"):
            found.append((event.channel, dream.drawing_t.decode(event.data)))
    return found


def check_same_run(dream, with_drawing, without):
    a = poses_by_step(dream, os.path.join(with_drawing, "run.lcmlog"))
    b = poses_by_step(dream, os.path.join(without, "run.lcmlog"))
    check(len(a) == STEPS + 1 and a.keys() == b.keys(), f"steps: {len(a)} with drawing, {len(b)} without")
    differ = [step for step in a if a[step] != b[step]]
    check(not differ, f"drawing changed the poses at steps {differ[:5]}...")
    sa, sb = read_summary(with_drawing), read_summary(without)
    check(sa["verdict"] == sb["verdict"] and sa["metrics"] == sb["metrics"],
          f"summaries differ: {sa['verdict']} {sa['metrics']} / {sb['verdict']} {sb['metrics']}")


def check_log_diff(ctx, args, run_dir, plain_dir):
    """dream log diff: every channel but the drawings is the same, message for message."""
    code, out = ctx.run([args.dream, "log", "diff", run_dir, plain_dir, "--channels", "(?!DREAM_DRAW_).*"], timeout=60)
    check(code == 0, f"dream log diff of every channel but DREAM_DRAW_*: exit {code}: {out[-600:]}")
    code, out = ctx.run([args.dream, "log", "diff", run_dir, plain_dir], timeout=60)
    check(code == 1 and "DREAM_DRAW_0" in out, f"dream log diff of the whole logs: exit {code}: {out[-600:]}")


def check_logged(dream, run_dir, plain_dir):
    drawings = drawings_of(dream, os.path.join(run_dir, "run.lcmlog"))
    run_id = dream.robot_poses_t.decode(next(e.data for e in read_events(os.path.join(run_dir, "run.lcmlog"))
                                             if e.channel == "DREAM_POSES")).run_id
    robots = {channel for channel, _ in drawings}
    check(robots == {"DREAM_DRAW_0", "DREAM_DRAW_1", "DREAM_DRAW_2"}, f"drawings logged on {sorted(robots)}")
    # Each update draws its step's text: a new drawing every step from step 1 on.
    check(len(drawings) >= 3 * (STEPS - 2), f"{len(drawings)} drawings logged over {STEPS} steps of 3 robots")
    for channel, d in drawings:
        check(d.run_id == run_id and channel == f"DREAM_DRAW_{d.robot_id}" and d.clipped == 0,
              f"{channel}: a drawing of robot {d.robot_id}, run {d.run_id:x}, clipped {d.clipped}")
        kinds = list(d.kind)
        check(kinds[:4] == [1, 2, 4, 5] and kinds[4:] == ([3] if d.robot_id == 0 else []),
              f"{channel} step {d.step}: kinds {kinds}")
        check(d.text.decode("utf-8") == f"r{d.robot_id} k={d.step}", f"{channel} step {d.step}: text {d.text!r}")
    check(not drawings_of(dream, os.path.join(plain_dir, "run.lcmlog")), "the run without drawing logged drawings")


def check_rendered(ctx, args, run_dir, plain_dir):
    with_png, without_png = ctx.path("with.png"), ctx.path("without.png")
    ctx.run([args.dream, "render", run_dir, "--out", with_png], timeout=60, expect=0)
    ctx.run([args.dream, "render", plain_dir, "--out", without_png], timeout=60, expect=0)
    shown, plain = green_pixels(with_png), green_pixels(without_png)
    check(shown > 2000, f"the rendered picture of the drawing run has {shown} pixels of the green square")
    check(plain == 0, f"the picture of the run without drawing has {plain} green pixels")
    left_out = ctx.path("no_drawings.png")
    ctx.run([args.dream, "render", run_dir, "--out", left_out, "--no-drawings"], timeout=60, expect=0)
    hidden = green_pixels(left_out)
    check(hidden == 0, f"the picture of the drawing run with --no-drawings has {hidden} green pixels")
    # trajectories.png, written by the run itself, shows the last step's drawing too.
    check(green_pixels(os.path.join(run_dir, "trajectories.png")) > 2000, "trajectories.png has no green square")
    gif, last = ctx.path("run.gif"), ctx.path("last.png")
    ctx.run([args.dream, "render", run_dir, "--out", gif, "--fps", "10", "--width", "640"], timeout=120, expect=0)
    subprocess.run(["ffmpeg", "-v", "error", "-sseof", "-0.3", "-i", gif, "-frames:v", "1", "-y", last], check=True)
    in_video = green_pixels(last)
    check(in_video > 400, f"the video's last frame has {in_video} pixels of the green square")


def check_echo(ctx, args, run_dir):
    _, out = ctx.run([args.dream, "log", "echo", run_dir, "DREAM_DRAW_0", "--limit", "1"], timeout=60, expect=0)
    first = json.loads(next(line for line in out.splitlines() if line.startswith("{")))
    check(first["channel"] == "DREAM_DRAW_0" and first["type"] == "drawing_t", f"dream log echo: {out[:400]}")
    message = first["message"]
    check(message["text"] == "r0 k=1" and message["kind"] == [1, 2, 4, 5, 3] and message["num_shapes"] == 5,
          f"dream log echo of DREAM_DRAW_0: {out[:400]}")


def test(ctx):
    args = argument_parser(types_dir=True).parse_args()
    dream = import_types(args.types_dir)
    with open(ctx.path("painter.py"), "w") as f:
        f.write(CONTROLLER)
    config = ctx.path("drawing.yaml")
    with open(config, "w") as f:
        f.write(CONFIG)
    run_dir, plain_dir = ctx.path("with"), ctx.path("without")
    ctx.run([args.dream, "run", config, "--out", run_dir, "--set", "controller.draw=true"], timeout=120, expect=0)
    ctx.run([args.dream, "run", config, "--out", plain_dir], timeout=120, expect=0)
    check_same_run(dream, run_dir, plain_dir)
    check_log_diff(ctx, args, run_dir, plain_dir)
    check_logged(dream, run_dir, plain_dir)
    check_rendered(ctx, args, run_dir, plain_dir)
    check_echo(ctx, args, run_dir)


if __name__ == "__main__":
    main(test)
