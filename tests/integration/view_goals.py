#!/usr/bin/python3
"""view_goals: `dream view` draws a Python controller's own goal points (its class's
goal_points()), with the tutorial's ring (docs/tutorial.md's ring.py and ring.yaml).

What the page is sent is read at the JSON level: the setup message on the view's WebSocket
(`/ws`, its first message) live, and `/run.json` in replay.
- live, `dream view --config ring.yaml` (on memq://: nothing leaves the process): the ring's six
  points, computed once before the view starts;
- `dream run ring.yaml --view`: the same points, in the run's own view;
- replay, `dream view runs/ring`: summary.json's metrics.goal_points (what the run was judged
  with: a summary.json edited to other points shows those), and without summary.json, the points
  computed from config.yaml;
- a goal_points() that raises: the view starts anyway, draws no goals and says why (the file and
  line of the exception);
- replay: the setup carries summary.json's verdict and goal, which the page shows at the run's end.
And `--fps`: the page is told the rate (it draws no more often); 0 is refused.

Usage: view_goals.py --dream BIN --source DIR
"""

import json
import math
import os
import re
import shutil
import urllib.request

from devtools import WebSocket
from dreamtest import Context, arguments, check, main, read_summary

URL = re.compile(r"open (http://127\.0\.0\.1:(\d+)/)")


def code_blocks(text, language):
    return re.findall(r"```" + language + r"\n(.*?)```", text, flags=re.S)


def setup_message(ctx, name):
    """The setup message the view of process `name` sends a new browser first."""
    ctx.wait_for_output(name, URL.pattern, 30)
    port = URL.search(ctx.output(name)).group(2)
    socket = WebSocket(f"ws://127.0.0.1:{port}/ws")
    try:
        while True:
            message = json.loads(socket.receive())
            if message.get("type") == "setup":
                return message
    finally:
        socket.close()


def same_points(shown, expected, tolerance=1e-4):
    return len(shown) == len(expected) and all(
        len(a) == len(b) and all(abs(p[0] - q[0]) <= tolerance and abs(p[1] - q[1]) <= tolerance for p, q in zip(a, b))
        for a, b in zip(shown, expected))


def test(ctx):
    args = arguments()
    with open(os.path.join(args.source, "docs", "tutorial.md")) as f:
        tutorial = f.read()
    folder = ctx.path("experiment")
    os.makedirs(folder)
    for name, text in (("ring.py", code_blocks(tutorial, "python")[0]), ("ring.yaml", code_blocks(tutorial, "yaml")[0])):
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    os.chdir(folder)

    # The run first: summary.json's goal points are what the view must draw in replay.
    ctx.run([args.dream, "run", "ring.yaml", "-q"], timeout=120, expect=0)
    declared = read_summary("runs/ring")["metrics"]["goal_points"]
    check(len(declared) == 6 and all(len(p) == 1 and abs(math.hypot(*p[0]) - 0.6) < 1e-9 for p in declared),
          f"the ring's goal points (one a robot, 0.6 m from the centre): {declared}")

    ctx.start("live", [args.dream, "view", "--config", "ring.yaml", "--port", "0", "--lcm-url", "memq://",
                       "--fps", "12"])
    setup = setup_message(ctx, "live")
    live = setup["goals"]
    check(same_points(live, declared), f"dream view --config ring.yaml draws goals {live}, the run declared {declared}")
    check(setup["fps"] == 12, f"dream view --fps 12: the page is told {setup['fps']} frames a second")
    ctx.stop("live")

    ctx.start("embedded", [args.dream, "run", "ring.yaml", "--out", "embedded", "--steps", "90", "--view",
                           "--view-port", "0", "--pace", "1", "-q"])
    embedded = setup_message(ctx, "embedded")["goals"]
    check(same_points(embedded, declared), f"dream run --view draws goals {embedded}, the run declared {declared}")
    ctx.wait("embedded", 30)

    # Replay: summary.json's points; to tell them from points computed again, it is given others.
    with open("runs/ring/summary.json") as f:
        summary = json.load(f)
    moved = [[[x + 0.1, y] for x, y in points] for points in declared]
    summary["metrics"]["goal_points"] = moved
    with open("runs/ring/summary.json", "w") as f:
        json.dump(summary, f)
    ctx.start("replay", [args.dream, "view", "runs/ring", "--port", "0"])
    ctx.wait_for_output("replay", URL.pattern, 30)
    with urllib.request.urlopen(URL.search(ctx.output("replay")).group(1) + "run.json", timeout=30) as response:
        replayed = json.load(response)["goals"]
    check(same_points(replayed, moved), f"the replay draws goals {replayed}, its summary.json declares {moved}")
    # One judge (issue 33): at the run's end the page shows summary.json's verdict and goal, not its own.
    judged = setup_message(ctx, "replay").get("judged")
    check(judged is not None and judged["verdict"] == summary["verdict"]
          and judged["goal"].startswith("met" if summary["goal"]["met"] else "missed"),
          f"the replay's setup should carry summary.json's verdict {summary['verdict']} and goal "
          f"{summary['goal']}: {judged}")
    ctx.stop("replay")

    os.remove("runs/ring/summary.json")
    ctx.start("computed", [args.dream, "view", "runs/ring", "--port", "0"])
    ctx.wait_for_output("computed", URL.pattern, 30)
    with open(os.path.join("runs", "ring", "config.yaml")) as f:
        check("class: Ring" in f.read(), "runs/ring/config.yaml is not the ring's")
    with urllib.request.urlopen(URL.search(ctx.output("computed")).group(1) + "run.json", timeout=30) as response:
        computed = json.load(response)["goals"]
    check(same_points(computed, declared), f"without summary.json the replay draws goals {computed}, "
                                           f"goal_points() gives {declared}")
    ctx.stop("computed")

    # A goal_points() that raises: the view still starts, with no goals, and says why.
    with open("ring.py") as f:
        module = f.read()
    shutil.copy("ring.yaml", "broken.yaml")
    with open("ring.py", "w") as f:
        f.write(module.replace("        return [[ring_point(", "        raise ValueError('no ring here')\n"
                                                                "        return [[ring_point("))
    ctx.start("broken", [args.dream, "view", "--config", "broken.yaml", "--port", "0", "--lcm-url", "memq://"])
    broken = setup_message(ctx, "broken")["goals"]
    output = ctx.output("broken")
    check(broken == [], f"a goal_points() that raised drew goals {broken}")
    check(re.search(r"without the controller's goal points: .*ValueError: no ring here \(.*ring\.py:\d+\)", output),
          f"dream view does not say why it draws no goals: {output[-600:]}")
    ctx.stop("broken")
    code, output = ctx.run([args.dream, "view", "--fps", "0", "--lcm-url", "memq://"], timeout=30)
    check(code != 0 and "--fps" in output, f"dream view --fps 0: exit {code}: {output[-300:]}")
    print(f"goals drawn: live, dream run --view, replay (summary.json and computed): {len(declared)} robots")


if __name__ == "__main__":
    main(test)
