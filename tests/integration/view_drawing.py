#!/usr/bin/python3
"""view_drawing: what controllers draw shows in dream view, live and in replay, in headless
Chromium (issue 37 item 4).

`dream run --view --view-wait` of drawing_run's three-robot Python controller with drawing on
(memq: nothing leaves the process). Live: the page's state lists each robot's shapes of a step
(line, circle, arrow, text, and robot 0's filled square) with the text of the step drawn (or one
just before, the newest heard), and the arena canvas has the square's green pixels. At the end,
the replay at its last step shows them too; scrubbed back to a step, the texts are that step's;
unticking the *drawings* layer leaves no green pixel. Screenshots: drawing_live.png,
drawing_replay.png.

Every wait is on the page's state; the time-outs only turn a page that never gets there into a
failure.

Usage: view_drawing.py --dream BIN --source DIR --artifacts DIR
"""

import os
import re
import signal
import time

from devtools import Page, chromium_argv, devtools_port, view_state, wait_for_view
from drawing_run import CONFIG, CONTROLLER, STEPS
from dreamtest import argument_parser, check, main

URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")
GREEN_ON_CANVAS = """(() => {
    const c = document.getElementById('arena');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 40 && d[i + 1] > 160 && d[i + 1] < 240 && d[i + 2] < 40) n++;
    return n;
})()"""


def step_of_text(text):
    match = re.fullmatch(r"r(\d+) k=(\d+)", text)
    return (int(match.group(1)), int(match.group(2))) if match else None


def check_drawn(page, shown, where, steps):
    """The three robots' drawings at one of `steps`, and the green square on the canvas."""
    d = shown["drawings"]
    check(d["shown"] and sorted(d["robots"]) == [0, 1, 2] and d["clipped"] == 0,
          f"{where}: drawings of robots {d['robots']} (clipped {d['clipped']})")
    check(d["kinds"] == {"line": 3, "circle": 3, "arrow": 3, "text": 3, "polygon": 1}, f"{where}: shapes {d['kinds']}")
    texts = sorted(step_of_text(t) or (-1, -1) for t in d["texts"])
    check([robot for robot, _ in texts] == [0, 1, 2] and all(k in steps for _, k in texts),
          f"{where} (step {shown['step']}): texts {d['texts']}, expected one of steps {sorted(steps)}")
    green = page.evaluate(GREEN_ON_CANVAS)
    check(green > 300, f"{where}: {green} green pixels of robot 0's square on the arena canvas")


def watch_live(page, artifacts):
    seen = 0
    while True:
        # A frame may be sent between one robot's drawing and the next's (each is its own message):
        # wait for one holding all three, then check it.
        shown = wait_for_view(page, "a live step with every robot's drawing",
                              lambda s: s["mode"] == "replay" or (s["mode"] == "live" and s["drawings"]["shapes"] and
                                                                  len(s["drawings"]["robots"]) == 3), 60)
        if shown["mode"] == "replay":
            break
        step = shown["step"]
        check_drawn(page, shown, "live", {step, step - 1, step - 2})
        seen += 1
        if seen == 3:
            page.screenshot(os.path.join(artifacts, "drawing_live.png"))
        if seen >= 5:
            break
    check(seen >= 1, "live: no step with drawings was seen before the replay")


def test(ctx):
    parser = argument_parser(types_dir=True)
    parser.add_argument("--artifacts", required=True, help="where the screenshots are kept")
    args = parser.parse_args()
    os.makedirs(args.artifacts, exist_ok=True)
    with open(ctx.path("painter.py"), "w") as f:
        f.write(CONTROLLER)
    config, run_dir = ctx.path("drawing.yaml"), ctx.path("run")
    with open(config, "w") as f:
        f.write(CONFIG)
    ctx.start("run", [args.dream, "run", config, "--out", run_dir, "--set", "controller.draw=true", "--view",
                      "--view-port", "0", "--view-wait", "--pace", "1", "--view-keep", "ctrl-c"])
    ctx.wait_for_output("run", URL.pattern, 30)
    url = URL.search(ctx.output("run")).group(1)
    ctx.start("chromium", chromium_argv(ctx.path("chrome"), url), own_group=True)
    page = Page(devtools_port(ctx.path("chrome")))
    ctx.wait_for_output("run", r"a browser is watching: the run starts", 60)
    watch_live(page, args.artifacts)
    ended = wait_for_view(page, "the run's replay at its last step",
                          lambda s: s["mode"] == "replay" and s["step"] == STEPS, 90)
    check_drawn(page, ended, "the replay's end", {STEPS - 2, STEPS - 1, STEPS})
    step = 30
    page.evaluate(f"(() => {{ const s = document.getElementById('scrub'); s.value = '{step}';"
                  " s.dispatchEvent(new Event('input')); })()")
    shown = wait_for_view(page, f"the replay at step {step}", lambda s: s["step"] == step, 20)
    check_drawn(page, shown, f"replay at step {step}", {step})
    page.screenshot(os.path.join(args.artifacts, "drawing_replay.png"))
    page.evaluate("document.getElementById('show-drawings').click()")
    # The page redraws on the change (view_state is republished only by a frame): wait for the canvas.
    deadline = time.monotonic() + 20
    while (green := page.evaluate(GREEN_ON_CANVAS)) > 0 and time.monotonic() < deadline:
        time.sleep(0.05)
    check(green == 0 and view_state(page)["step"] == step, f"the drawings layer off leaves {green} green pixels")
    page.close()
    ctx.procs["run"][0].send_signal(signal.SIGINT)
    code = ctx.wait("run", 20)
    check(code == 0, f"dream run --view of the drawing run: exit {code}")


if __name__ == "__main__":
    main(test)
