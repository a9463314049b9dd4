#!/usr/bin/python3
"""view_verdict: `dream run --view` ends on the run's one verdict and its page outlives the run
(issues 33 item 3, 37 item 1). memq only: nothing leaves the processes.

What the page is sent is read at the JSON level (the WebSocket's setup, /run.json):
- at the run's end the same URL serves the finished run as a replay whose setup carries
  summary.json's verdict, goal and metrics: a run that missed its goal (the README's go_to_goal
  judged at 1 mm; exit 5) ends `not_ready` with the goal missed, one that met it `clean` with the goal met; the console prints the replay
  command; Ctrl-C ends the serving and the exit code stays the run's;
- a page open during the run is sent the replay's setup when the run ends (it switches by itself),
  and by default (`--view-keep watched`) the page is served until Ctrl-C while a browser is there;
- `--view-wait`: no step before a browser connects (the run folder holds no summary until then);
  Ctrl-C while waiting runs nothing (exit 130); `--view-wait-timeout` starts the run anyway;
- bad `--view-keep`, and `--view-wait` without `--view`, are refused;
- `dream view RUN` of a summary.json that dream did not write (a verdict that is no text, metrics
  that are no mapping, 5000 metrics): the counts' verdict with a warning, no metrics, 64 metrics.
Every wait is on an event (a console line, a message, a process's exit), never on a time margin.

Usage: view_verdict.py --dream BIN --source DIR
"""

import json
import os
import re
import signal
import urllib.request

from devtools import WebSocket
from dreamtest import Context, arguments, check, main, read_summary

URL = re.compile(r"open (http://127\.0\.0\.1:(\d+)/)")
MISSED = ["--set", "controller.goal_tolerance_m=0.001"]
REPLAYED = r"the run is over; \S+ replays it\. Later: dream view (\S+)"


def page_socket(ctx, name):
    ctx.wait_for_output(name, URL.pattern, 60)
    return WebSocket(f"ws://127.0.0.1:{URL.search(ctx.output(name)).group(2)}/ws", timeout=120)


def next_setup(socket, mode):
    """The next setup message of `mode` on an open page's WebSocket (live frames before it are skipped)."""
    while True:
        message = json.loads(socket.receive())
        if message.get("type") == "setup" and message.get("mode") == mode:
            return message


def check_judged(setup, summary, where):
    """The replay's setup carries summary.json's verdict, goal and scalar metrics."""
    judged = setup.get("judged")
    check(judged is not None, f"{where}: the replay's setup has no verdict: {json.dumps(setup)[:300]}")
    check(judged["verdict"] == summary["verdict"],
          f"{where}: the page ends on {judged['verdict']}, summary.json says {summary['verdict']}")
    goal = summary["goal"]
    expected = "met" if goal["met"] else "missed"
    check(judged["goal"].startswith(expected) and goal["detail"] in judged["goal"],
          f"{where}: the page's goal is '{judged['goal']}', summary.json's {goal}")
    metrics = dict(judged["metrics"])
    for name, value in summary["metrics"].items():
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            check(name in metrics and abs(float(metrics[name]) - value) <= 1e-5 * max(1.0, abs(value)),
                  f"{where}: metric {name} = {value} in summary.json, the page lists {metrics.get(name)}")


def run_to_replay(ctx, args, name, extra, expect):
    """dream run --view --view-keep ctrl-c: the replay read at its end, then Ctrl-C; the run's exit code."""
    ctx.start(name, [args.dream, "run", "config/go_to_goal.yaml", "--out", ctx.path(name), "--view",
                     "--view-port", "0", "--pace", "0", "--view-keep", "ctrl-c", "-q"] + extra)
    ctx.wait_for_output(name, REPLAYED, 120)
    output = ctx.output(name)
    check(re.search(REPLAYED, output).group(1) == ctx.path(name), f"{name}: the replay command: {output[-300:]}")
    socket = page_socket(ctx, name)
    try:
        setup = next_setup(socket, "replay")
    finally:
        socket.close()
    port = URL.search(output).group(2)
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/run.json", timeout=60) as response:
        run = json.load(response)
    summary = read_summary(ctx.path(name))
    check(len(run["steps"]) == summary["steps"] + 1, f"{name}: /run.json has {len(run['steps'])} steps, "
                                                     f"summary.json {summary['steps']} (+ step 0)")
    check_judged(setup, summary, name)
    check(ctx.procs[name][0].poll() is None, f"{name}: --view-keep ctrl-c stopped serving by itself")
    ctx.procs[name][0].send_signal(signal.SIGINT)
    code = ctx.wait(name, 60)
    check(code == expect, f"{name}: exit {code} after Ctrl-C while serving the replay; the run's is {expect}")
    return summary


def replay_setup(ctx, args, name, run_dir):
    ctx.start(name, [args.dream, "view", run_dir, "--port", "0"])
    socket = page_socket(ctx, name)
    try:
        return next_setup(socket, "replay")
    finally:
        socket.close()
        ctx.stop(name)


def damaged_summaries(ctx, args):
    """A summary.json that is not what dream wrote: the replay shows the counts' verdict (a warning
    naming the file), or at most 64 metrics of a summary listing thousands."""
    with open(ctx.path("met", "summary.json")) as f:
        summary = json.load(f)
    for name, damage in (("verdict_not_text", {"verdict": 5}), ("metrics_not_object", {"metrics": [1, 2]}),
                         ("many_metrics", {"metrics": {f"m{i}": i for i in range(5000)}})):
        run_dir = ctx.path(name)
        os.makedirs(run_dir)
        for file in ("run.lcmlog", "config.yaml"):
            os.link(ctx.path("met", file), os.path.join(run_dir, file))
        with open(os.path.join(run_dir, "summary.json"), "w") as f:
            json.dump({**summary, **damage}, f)
        judged = replay_setup(ctx, args, "view_" + name, run_dir).get("judged")
        if name == "verdict_not_text":
            check(judged is None and "summary.json: not read" in ctx.output("view_" + name),
                  f"a summary.json whose verdict is 5: judged {judged}: {ctx.output('view_' + name)[-300:]}")
        elif name == "metrics_not_object":
            # summary.json's field list (node::RunSummary) says metrics is an object: the file is refused, named.
            named = "summary.json: metrics: expected an object, got [1,2]" in ctx.output("view_" + name)
            check(judged is None and named,
                  f"a summary.json whose metrics are a list: judged {judged}: {ctx.output('view_' + name)[-300:]}")
        else:
            check(judged is not None and len(judged["metrics"]) == 64,
                  f"5000 metrics in summary.json: the page lists {len(judged['metrics']) if judged else None}")


def test(ctx):
    args = arguments()
    os.chdir(args.source)

    # The goal missed (robots stop within 2 cm, judged at 1 mm): not_ready, exit 5, at the end and in the page.
    missed = run_to_replay(ctx, args, "missed", MISSED, 5)
    check(missed["verdict"] == "not_ready" and not missed["goal"]["met"], f"60 steps: {missed['goal']}")
    met = run_to_replay(ctx, args, "met", [], 0)
    check(met["verdict"] == "clean" and met["goal"]["met"], f"the README's go_to_goal: {met['goal']}")
    damaged_summaries(ctx, args)

    # --view-wait: nothing runs before a browser; the open page switches to the replay by itself.
    ctx.start("wait", [args.dream, "run", "config/go_to_goal.yaml", "--out", ctx.path("wait"), "--view",
                       "--view-port", "0", "--pace", "0", "--view-wait", "-q"] + MISSED)
    ctx.wait_for_output("wait", r"waiting for a browser at http://127\.0\.0\.1:\d+/ before step 0 \(Ctrl-C", 60)
    check(not os.path.exists(ctx.path("wait", "summary.json")) and ctx.procs["wait"][0].poll() is None,
          "--view-wait ran the run before a browser came")
    socket = page_socket(ctx, "wait")
    try:
        check(json.loads(socket.receive())["mode"] == "live", "--view-wait: the page is not live at first")
        setup = next_setup(socket, "replay")
        ctx.wait_for_output("wait", r"a browser is watching: serving until Ctrl-C", 60)
    finally:
        socket.close()
    check_judged(setup, read_summary(ctx.path("wait")), "--view-wait")
    ctx.procs["wait"][0].send_signal(signal.SIGINT)
    check(ctx.wait("wait", 60) == 5, "--view-wait: Ctrl-C after the run changed its exit code")

    ctx.start("give-up", [args.dream, "run", "config/go_to_goal.yaml", "--out", ctx.path("give-up"), "--view",
                          "--view-port", "0", "--view-wait", "-q"])
    ctx.wait_for_output("give-up", r"waiting for a browser", 60)
    ctx.procs["give-up"][0].send_signal(signal.SIGINT)
    code = ctx.wait("give-up", 60)
    check(code == 130 and "nothing was run" in ctx.output("give-up"),
          f"Ctrl-C while waiting for a browser: exit {code}: {ctx.output('give-up')[-300:]}")
    check(not os.path.exists(ctx.path("give-up", "summary.json")), "Ctrl-C while waiting still ran the run")

    # No browser within the timeout: the run starts anyway, and with nobody watching it ends with the run.
    code, output = ctx.run([args.dream, "run", "config/go_to_goal.yaml", "--out", ctx.path("timeout"), "--view",
                            "--view-port", "0", "--pace", "0", "--view-wait", "--view-wait-timeout", "0.2",
                            "-q"] + MISSED, timeout=120)
    check(code == 5 and "no browser within 0.2 s: the run starts" in output and re.search(REPLAYED, output),
          f"--view-wait-timeout 0.2: exit {code}: {output[-400:]}")

    code, output = ctx.run([args.dream, "run", "config/go_to_goal.yaml", "--view", "--view-keep", "soon"])
    check(code == 1 and "--view-keep soon" in output, f"--view-keep soon: exit {code}: {output[-300:]}")
    code, output = ctx.run([args.dream, "run", "config/go_to_goal.yaml", "--view-wait"])
    check(code == 2 and "--view" in output, f"--view-wait without --view: exit {code}: {output[-300:]}")
    print("dream run --view: ends on summary.json's verdict (missed: not_ready, met: clean), replay served; "
          "--view-wait, its Ctrl-C and timeout")


if __name__ == "__main__":
    main(test)
