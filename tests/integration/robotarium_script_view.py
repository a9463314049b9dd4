#!/usr/bin/python3
"""robotarium_script_view: a Robotarium script's run is watched as any run (docs/robotarium-scripts.md#watching).

The script (DREAM's rps only) asks for show_figure=True and drives three robots for a few dozen steps.
- `dream run SCRIPT.py` without --view serves no page (show_figure=True opens nothing) and exits 0;
  `dream view RUN` of its folder replays it: the page's replay setup carries summary.json's verdict,
  and /run.json holds every step of the log;
- `dream run SCRIPT.py --view --view-wait`: no step before a browser has the page (the run folder has
  no summary.json yet); the page is live first, gets frames of the script's three robots while the run
  is paced to real time (--view's default; 60 steps, 2 s), then switches by itself
  to the replay of the finished run with summary.json's verdict; Ctrl-C ends the serving and the exit
  code stays the run's (0).
Every wait is on an event (a console line, a message, a process's exit), never on a time margin.

Skipped (77) without numpy or cvxopt.
Usage: robotarium_script_view.py --dream BIN --source DIR
"""

import json
import os
import re
import signal
import urllib.request

from devtools import WebSocket
from dreamtest import arguments, check, main, read_summary, script_under_test, tail

URL = re.compile(r"open (http://127\.0\.0\.1:(\d+)/)")
SCRIPT = """
import numpy as np
import rps.robotarium as robotarium
from rps.utilities.transformations import create_si_to_uni_dynamics

N = 3
r = robotarium.Robotarium(number_of_robots=N, show_figure=True, sim_in_real_time=True,
                          initial_conditions=np.array([[-0.8, 0.0, 0.8], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]))
si_to_uni = create_si_to_uni_dynamics()
goals = np.array([[-0.8, 0.0, 0.8], [0.4, 0.4, 0.4]])
for _ in range(60):
    x = r.get_poses()
    r.set_velocities(np.arange(N), si_to_uni(0.5 * (goals - x[:2, :]), x))
    r.step()
r.debug()
"""


def next_setup(socket, mode):
    while True:
        message = json.loads(socket.receive())
        if message.get("type") == "setup" and message.get("mode") == mode:
            return message


def check_replay(setup, run_dir, port, where):
    summary = read_summary(run_dir)
    judged = setup.get("judged")
    check(judged is not None and judged["verdict"] == summary["verdict"],
          f"{where}: the replay ends on {judged and judged['verdict']}, summary.json says {summary['verdict']}")
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/run.json", timeout=60) as response:
        run = json.load(response)
    check(len(run["steps"]) == summary["steps"] + 1,
          f"{where}: /run.json has {len(run['steps'])} steps, summary.json {summary['steps']} (+ step 0)")
    return summary


def test(ctx):
    args = arguments()
    script = script_under_test(ctx, "watched_script.py", SCRIPT)

    # show_figure=True without --view: no page; the finished run replays with dream view.
    plain = ctx.path("plain")
    code, output = ctx.run([args.dream, "run", script, "--out", plain], timeout=300)
    check(code == 0 and not URL.search(output), f"dream run SCRIPT.py (show_figure=True): exit {code}, "
                                                f"a page served: {bool(URL.search(output))}: {tail(output)}")
    ctx.start("replay", [args.dream, "view", plain, "--port", "0"])
    ctx.wait_for_output("replay", URL.pattern, 60)
    port = URL.search(ctx.output("replay")).group(2)
    socket = WebSocket(f"ws://127.0.0.1:{port}/ws", timeout=120)
    try:
        check_replay(next_setup(socket, "replay"), plain, port, "dream view of a script's run")
    finally:
        socket.close()
        ctx.stop("replay")

    # --view --view-wait: live from the first step, then the replay at the same URL.
    watched = ctx.path("watched")
    ctx.start("watched", [args.dream, "run", script, "--out", watched, "--view", "--view-port", "0",
                          "--view-wait", "--view-keep", "ctrl-c", "-q"])
    ctx.wait_for_output("watched", r"waiting for a browser at http://127\.0\.0\.1:\d+/ before step 0", 120)
    check(not os.path.exists(os.path.join(watched, "summary.json")), "--view-wait ran the script's run before a "
                                                                      "browser came")
    port = re.search(r"waiting for a browser at http://127\.0\.0\.1:(\d+)/", ctx.output("watched")).group(1)
    socket = WebSocket(f"ws://127.0.0.1:{port}/ws", timeout=120)
    try:
        live = json.loads(socket.receive())
        check(live.get("type") == "setup" and live.get("mode") == "live",
              f"the page of a script's run is not live at first: {json.dumps(live)[:300]}")
        # Paced to real time (--view's default): the page gets live frames of the script's 3 robots.
        frames = []
        while True:
            message = json.loads(socket.receive())
            if message.get("type") == "frame":
                frames.append(message)
            elif message.get("type") == "setup" and message.get("mode") == "replay":
                replay = message
                break
        check(frames and all(len(frame["x"]) == 3 for frame in frames),
              f"the live page got {len(frames)} frames, robots per frame {[len(f['x']) for f in frames][:5]}")
    finally:
        socket.close()
    summary = check_replay(replay, watched, port, "dream run SCRIPT.py --view")
    check(summary["verdict"] in ("clean", "warning"), f"the watched script's run: {summary['verdict']}")
    check(ctx.procs["watched"][0].poll() is None, "--view-keep ctrl-c stopped serving by itself")
    ctx.procs["watched"][0].send_signal(signal.SIGINT)
    code = ctx.wait("watched", 60)
    check(code == 0, f"Ctrl-C while serving the replay changed the run's exit code to {code}: "
                     f"{tail(ctx.output('watched'))}")


if __name__ == "__main__":
    main(test)
