#!/usr/bin/python3
"""view_metrics: the run's metrics over time beside the arena, in headless Chromium (issue 37 item 3).

`dream run --view --view-wait` of a three-robot go_to_goal (memq: nothing leaves the process):
Chromium opens the page before step 0. Live, the page must plot the kind's figures and the safety
figures (final_max_goal_error_m, min_pairwise_distance_m, ...), each following the run: the value
shown is the one of the step it says (computed on the view's metrics thread: the arena's step or one
just before, never after), and the goal's error falls as the robots drive in. The goal's
threshold (goal_tolerance_m) and the collision distance are drawn: red pixels on the plot's canvas
where the page says each line is. At the end the page becomes the run's replay at its last step,
where every plotted figure is summary.json's. Then the replay's timeline: scrubbed back, the plots
follow it (the figure at that step, the same number the page was sent live at that step), and the
*metrics over time* layer hides them. Screenshots: metrics_live.png, metrics_replay.png.

Every wait is on the page's state or a console line; the time-outs only turn a page that never
gets there into a failure.

A Python controller's metrics() live too: `dream run --view` of the shipped go_to_goal_python, its
class's own figure plotted while the run runs (computed by a helper process, each reading of a
step not after the arena's).

The command arrows too (issue 37 item 2): live, each is the robot's command for the step drawn
(or one just before, the newest heard); in replay, the log's command of the step drawn.

Usage: view_metrics.py --dream BIN --source DIR --types-dir DIR --artifacts DIR
"""

import json
import os
import re
import signal
import time

from devtools import Page, chromium_argv, devtools_port, view_state, wait_for_view
from dreamtest import argument_parser, check, import_types, main, read_events, read_summary

STEPS = 300
TOLERANCE = 0.05
CONFIG = f"""name: metrics_plot
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
  kind: go_to_goal
  gain: 0.8
  max_speed_mps: 0.15
  tolerance_m: 0.02
  goal_tolerance_m: {TOLERANCE}
  goals:
    - [0.0, 0.5]
    - [0.0, 0.0]
    - [0.0, -0.5]
"""
URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")
GOAL = "final_max_goal_error_m"
SAFETY = "min_pairwise_distance_m"


def figure(shown, name):
    for m in shown.get("metrics") or []:
        if m["name"] == name:
            return m
    return None


def red_pixels_on_threshold(page, name):
    """[row, red pixels]: where the plot drawn last puts `name`'s threshold line (device pixels) and
    how many clearly red pixels the canvas has on that row now; [null, 0] when it drew none."""
    return page.evaluate(f"""(() => {{
        const plot = window.dreamView.metricPlot;
        const panel = plot && plot.panels.find((p) => p.name === {json.dumps(name)});
        if (!panel || panel.thresholdY === null) return [null, 0];
        const c = document.getElementById('metric-plot');
        const d = c.getContext('2d').getImageData(0, panel.thresholdY, c.width, 1).data;
        let n = 0;
        for (let i = 0; i < d.length; i += 4) if (d[i] > 180 && d[i + 1] < 100 && d[i + 2] < 100) n++;
        return [panel.thresholdY, n];
    }})()""")


def commands_of(dream, log_path):
    """{(step, robot): (v, w)}: the commands the run's log holds."""
    commands = {}
    for event in read_events(log_path):
        if event.channel.startswith("DREAM_CMD_"):
            c = dream.velocity_command_t.decode(event.data)
            commands[(c.step, c.robot_id)] = (c.v, c.w)
    return commands


def check_live_commands(live_commands, commands):
    """Each command arrow drawn live is the robot's command for the step drawn or one just before
    (the newest heard when the frame was taken)."""
    check(live_commands, "live: no command arrow was ever sent")
    for (step, robot), (v, w) in live_commands.items():
        options = [commands.get((k, robot)) for k in (step, step - 1, step - 2)]
        check(any(o and abs(o[0] - v) < 1e-4 and abs(o[1] - w) < 1e-4 for o in options),
              f"live at step {step}: robot {robot}'s command arrow ({v}, {w}); the log's: {options}")


def check_thresholds_drawn(page, shown, where):
    plot = shown.get("metricPlot")
    check(plot and plot["panels"], f"{where}: no metric plot drawn: {json.dumps(shown.get('metricPlot'))}")
    panels = {p["name"]: p for p in plot["panels"]}
    for name, value in ((GOAL, TOLERANCE), (SAFETY, 0.135)):
        check(name in panels, f"{where}: no plot of {name}; plotted: {sorted(panels)}")
        m = figure(shown, name)
        check(m is not None and m["threshold"] == value,
              f"{where}: {name}'s threshold is {m and m['threshold']}, expected {value}")
        row, red = red_pixels_on_threshold(page, name)
        check(row is not None, f"{where}: {name}'s threshold has no line")
        check(red > 20, f"{where}: {name}'s threshold line at row {row}: {red} red pixels (a dashed line expected)")
    check(panels.get("near_miss_steps", {}).get("thresholdY", 0) is None,
          f"{where}: near_miss_steps has a threshold line it never declared")


def watch_live(ctx, args, page):
    """The plots during the run: the step shown, its figures, the goal's error falling."""
    samples = {}
    live_commands = {}
    drawn = shot = False
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        shown = view_state(page)
        if shown and shown.get("mode") == "replay":
            break
        goal = figure(shown or {}, GOAL)
        if shown and shown["mode"] == "live" and goal is not None and goal["value"] is not None:
            # Computed on the metrics' own thread, the figures may trail the arena's step, never lead it.
            check(goal["step"] <= shown["step"],
                  f"live: the plot shows {GOAL} of step {goal['step']}, after the arena's step {shown['step']}")
            samples[goal["step"]] = {m["name"]: m["value"] for m in shown["metrics"] if m["step"] == goal["step"]}
            for r in shown["robots"]:
                if r.get("cv") is not None:
                    live_commands[(shown["step"], r["id"])] = (r["cv"], r["cw"])
            if not drawn and len(samples) >= 3 and (shown.get("metricPlot") or {}).get("panels"):
                check_thresholds_drawn(page, shown, "live")
                drawn = True
            if not shot and shown["step"] >= STEPS // 2:
                page.screenshot(os.path.join(args.artifacts, "metrics_live.png"))
                shot = True
        time.sleep(0.02)
    check(len(samples) >= 3, f"live: the plots were seen at {len(samples)} steps (expected several)")
    check(drawn, "live: the metric plots were never drawn")
    steps = sorted(samples)
    first, last = samples[steps[0]][GOAL], samples[steps[-1]][GOAL]
    check(last < first, f"live: {GOAL} went from {first} at step {steps[0]} to {last} at step {steps[-1]}")
    return samples, live_commands


def check_end(page, run_dir):
    """The replay at the run's last step: every figure plotted is summary.json's."""
    ended = wait_for_view(page, "the run's replay at its last step",
                     lambda s: s["mode"] == "replay" and s["step"] == STEPS and s.get("metrics"), 60)
    summary = read_summary(run_dir)["metrics"]
    for m in ended["metrics"]:
        check(m["name"] in summary and isinstance(summary[m["name"]], (int, float)),
              f"the page plots {m['name']}, which summary.json's metrics do not have as a number")
        want = summary[m["name"]]
        check(m["step"] == STEPS and abs(m["value"] - want) <= 1e-6 * max(1.0, abs(want)),
              f"at the end the page plots {m['name']} = {m['value']} (step {m['step']}), summary.json {want}")
    check(summary[GOAL] <= TOLERANCE, f"the robots did not reach their goals: {summary[GOAL]}")
    return ended


def check_replay_timeline(page, samples, commands, artifacts):
    """Scrubbed back to a step seen live: the plots follow, with the numbers sent live; the
    command arrows are the log's commands of that step."""
    step = sorted(samples)[len(samples) // 2]
    page.evaluate(f"(() => {{ const s = document.getElementById('scrub'); s.value = '{step}';"
                  " s.dispatchEvent(new Event('input')); })()")
    shown = wait_for_view(page, f"the plots at step {step}",
                     lambda s: s["step"] == step and (s.get("metricPlot") or {}).get("step") == step, 20)
    for name, value in samples[step].items():
        m = figure(shown, name)
        check(m is not None and m["step"] == step and abs(m["value"] - value) <= 1e-6 * max(1.0, abs(value)),
              f"replay at step {step}: {name} = {m and m['value']}, live it was {value}")
    check_thresholds_drawn(page, shown, f"replay at step {step}")
    for r in shown["robots"]:
        want = commands.get((step, r["id"]))
        check(want is not None and r["cv"] is not None and abs(r["cv"] - want[0]) < 1e-4 and
              abs(r["cw"] - want[1]) < 1e-4,
              f"replay at step {step}: robot {r['id']}'s command arrow ({r['cv']}, {r['cw']}), the log's {want}")
    page.evaluate("(() => { document.getElementById('show-commands').click();"
                  " document.getElementById('show-velocities').click(); })()")
    page.screenshot(os.path.join(artifacts, "metrics_replay.png"))
    page.evaluate("document.getElementById('show-metrics').click()")
    hidden = page.evaluate("document.getElementById('metric-section').hidden")
    check(hidden is True, "the metrics layer unticked leaves the plots shown")


def watch_python_live(ctx, args):
    """A Python controller's metrics() live (issue 37 item 3): `dream run --view` of the shipped
    go_to_goal_python; the page plots the class's own figure, each reading of a step not after the
    arena's, at more than one step before the run ends (its last point, summary.json's, is
    ViewMetricsTest's)."""
    run_dir = ctx.path("python_run")
    ctx.start("python_run", [args.dream, "run", os.path.join(args.source, "config", "go_to_goal_python.yaml"),
                             "--out", run_dir, "--view", "--view-port", "0", "--view-wait", "--pace", "2",
                             "--view-keep", "0"])
    ctx.wait_for_output("python_run", URL.pattern, 30)
    url = URL.search(ctx.output("python_run")).group(1)
    ctx.start("chromium_python", chromium_argv(ctx.path("chrome_python"), url), own_group=True)
    page = Page(devtools_port(ctx.path("chrome_python")))
    ctx.wait_for_output("python_run", r"a browser is watching: the run starts", 60)
    seen = {}
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        shown = view_state(page)
        if not shown or shown.get("mode") == "replay" or ctx.procs["python_run"][0].poll() is not None:
            break
        own = figure(shown, GOAL)  # the class's metrics(): the python kind has no C++ figure of that name
        if shown.get("mode") == "live" and own is not None and own["value"] is not None:
            check(own["step"] <= shown["step"],
                  f"python live: {GOAL} of step {own['step']}, after the arena's step {shown['step']}")
            seen[own["step"]] = own["value"]
        time.sleep(0.02)
    page.close()
    code = ctx.wait("python_run", 60)
    check(code == 0, f"dream run --view of go_to_goal_python: exit {code}")
    check(len(seen) >= 2, f"python live: the class's {GOAL} was plotted at {len(seen)} steps (expected several)")


def test(ctx):
    parser = argument_parser(types_dir=True)
    parser.add_argument("--artifacts", required=True, help="where the screenshots are kept")
    args = parser.parse_args()
    dream = import_types(args.types_dir)
    os.makedirs(args.artifacts, exist_ok=True)
    config, run_dir = ctx.path("metrics.yaml"), ctx.path("run")
    with open(config, "w") as f:
        f.write(CONFIG)
    ctx.start("run", [args.dream, "run", config, "--out", run_dir, "--view", "--view-port", "0", "--view-wait",
                      "--pace", "2", "--view-keep", "ctrl-c"])
    ctx.wait_for_output("run", URL.pattern, 30)
    url = URL.search(ctx.output("run")).group(1)
    ctx.start("chromium", chromium_argv(ctx.path("chrome"), url), own_group=True)
    page = Page(devtools_port(ctx.path("chrome")))
    ctx.wait_for_output("run", r"a browser is watching: the run starts", 60)
    samples, live_commands = watch_live(ctx, args, page)
    ended = check_end(page, run_dir)
    check_thresholds_drawn(page, ended, "the replay's end")
    commands = commands_of(dream, os.path.join(run_dir, "run.lcmlog"))
    check_live_commands(live_commands, commands)
    check_replay_timeline(page, samples, commands, args.artifacts)
    page.close()
    ctx.procs["run"][0].send_signal(signal.SIGINT)
    code = ctx.wait("run", 20)
    check(code == 0, f"dream run --view of a clean run that met its goal: exit {code}")
    watch_python_live(ctx, args)


if __name__ == "__main__":
    main(test)
