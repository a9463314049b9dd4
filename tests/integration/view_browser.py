#!/usr/bin/python3
"""view_browser: `dream view` as headless Chromium draws it, live and in replay.

Live: `dream view --port 0` listens; Chromium (headless, driven over the DevTools protocol) opens
it; `dream launch` runs a three-robot config over udpm (in a private network namespace) where
robot 0 drives out of the arena and robot 1 into robot 2. The page's state (window.dreamView.state,
what it draws) must show the three robots with their ids at the positions the run's log holds for
the step shown, the step advancing, each violation marked where the log says it happened, the
counts of the run's summary and the verdict "rejected"; once the run is over, the page ends on the
world's DREAM_VERDICT: data-verdict, the label "verdict" and the goal line as summary.json has them
(issue 33), also when the log is played with lcm-logplayer; the kind's final_max_goal_error_m is
plotted with its threshold and ends on summary.json's (issue 37 item 3). A screenshot is kept (live.png).

A forged DREAM_POSES of a made-up run after the end (issue 34): the finished run stays drawn with
its violations, and the page's status line names the other run (other_world.png).

lcm-logplayer: the run's log played on the bus (4x) is drawn live too, from its start again. Then
the status line's "draw it instead": the other run is drawn from its next step.

Embedded: `dream run --view --pace 4` of the same config: the page follows it to its end (the end
of a run on the process's own memq bus, which no handler reads, comes from its log), where the same
URL turns into the run's replay at its last step showing summary.json's verdict and goal (one
judge, issue 33); the browser being there, the page is served until Ctrl-C, which leaves the run's
exit code, and the page keeps the replay without retrying (issue 37 item 1).

Replay: `dream view RUN` of that run; the page's timeline is driven as a user would (play, pause,
step forward and back, scrub, speed) and must show the log's poses at the chosen step, and only
the violations up to it; a robot clicked with the browser's mouse shows its pose, velocity and goal
as the log has them, the wheel zooms about the cursor, keys fit, step, play and let go (issue 37
item 2). Screenshots are kept (replay.png, inspect.png: robot 1 picked, zoomed, velocity arrows).

Usage: netns.sh view_browser.py --dream BIN --source DIR --types-dir DIR --artifacts DIR
"""

import json
import os
import re
import signal
import time

from devtools import Page, chromium_argv, devtools_port, view_state, wait_for_view
from dreamtest import (Udpm, argument_parser, check, fail, import_types, main, read_events, read_summary,
                       require_private_netns)

STEPS = 240
CONFIG = f"""name: clash
seed: 1
robots: 3
steps: {STEPS}
stop_when_done: false
world:
  mode: lockstep
initial_poses:
  - [1.2, 0.0, 0.0]
  - [-0.7, -0.5, 0.0]
  - [-0.2, -0.5, 3.1416]
obstacles:
  - center: [0.0, 0.5]
    size: [0.3, 0.2]
controller:
  kind: go_to_goal
  gain: 0.8
  max_speed_mps: 0.15
  tolerance_m: 0.02
  goals:
    - [1.9, 0.0]      # outside the arena: robot 0 leaves it
    - [-0.2, -0.5]    # where robot 2 stands: robot 1 runs into it
    - [-0.2, -0.5]
"""
FORGED_RUN_ID = 0x0BADC0FFEE
URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")
ARENA_X = 1.6


def wait_for_page(page, what, expression, predicate, timeout):
    deadline = time.monotonic() + timeout
    last = None
    while time.monotonic() < deadline:
        last = page.evaluate(expression)
        if predicate(last):
            return last
        time.sleep(0.05)
    fail(f"the page did not show {what} within {timeout} s: {json.dumps(last)[:300]}")


def poses_by_step(dream, log_path):
    poses = {}
    for event in read_events(log_path):
        if event.channel == "DREAM_POSES":
            message = dream.robot_poses_t.decode(event.data)
            poses[message.step] = message
    return poses


def check_robots(shown, poses, where):
    """The page's robots are the log's at the page's step (sent to 0.1 mm)."""
    step = shown["step"]
    check(step in poses, f"{where}: the page shows step {step}, which the log does not have")
    truth = poses[step]
    robots = shown["robots"]
    check([r["id"] for r in robots] == list(range(truth.num_robots)),
          f"{where}: robots {[r['id'] for r in robots]} drawn, the run has {truth.num_robots}")
    for r in robots:
        i = r["id"]
        error = max(abs(r["x"] - truth.x[i]), abs(r["y"] - truth.y[i]), abs(r["theta"] - truth.theta[i]))
        check(error < 1e-4, f"{where}: robot {i} drawn at ({r['x']}, {r['y']}, {r['theta']}) at step {step}, "
                            f"the log has ({truth.x[i]:.5f}, {truth.y[i]:.5f}, {truth.theta[i]:.5f})")


def check_marks(marks, poses, where):
    """Each violation marked is one at its step in the log: robot 0 outside, robots 1 and 2 too close."""
    kinds = {m["kind"] for m in marks}
    check({"boundary", "collision"} <= kinds, f"{where}: violations marked: {sorted(kinds)}; expected a boundary "
                                              f"and a collision")
    for m in marks:
        truth = poses[m["step"]]
        if m["kind"] == "boundary":
            check(m["robot"] == 0 and truth.x[0] > ARENA_X, f"{where}: boundary mark {m} but robot 0 is at "
                                                             f"x={truth.x[0]:.3f} at that step")
            check(abs(m["x"] - truth.x[0]) < 1e-4, f"{where}: boundary mark {m} is not where robot 0 was")
            check(abs(m["worst"] - (truth.x[0] - ARENA_X)) < 1e-4,
                  f"{where}: boundary mark {m}: robot 0 was {truth.x[0] - ARENA_X:.4f} m outside")
        elif m["kind"] == "collision":
            check((m["robot"], m["other"]) == (1, 2), f"{where}: collision mark {m}: expected robots 1 and 2")
            check(abs(m["x"] - (truth.x[1] + truth.x[2]) / 2) < 1e-4, f"{where}: collision mark {m} is not "
                                                                       f"between robots 1 and 2")
        else:
            fail(f"{where}: unexpected violation {m}")


def check_episodes(page, shown, where):
    """Issue 37: a violation held over steps is one episode in the page's list: each run of
    consecutive steps of one (kind, robots) is one entry, listed as 'steps FIRST-LAST'."""
    expected = []
    for m in sorted(shown["violations"], key=lambda m: m["step"]):
        key = (m["kind"], m["robot"], m["other"])
        check(isinstance(m.get("worst"), (int, float)), f"{where}: mark {m} has no worst value")
        going = next((e for e in reversed(expected) if e["key"] == key), None)
        if going and m["step"] <= going["last"] + 1:
            going["last"] = max(going["last"], m["step"])
            going["worst"] = (min if m["kind"] == "collision" else max)(going["worst"], m["worst"])
        else:
            expected.append({"key": key, "first": m["step"], "last": m["step"], "worst": m["worst"]})
    got = [((e["kind"], e["robot"], e["other"]), e["first"], e["last"], e["worst"]) for e in shown["episodes"]]
    check(sorted(got) == sorted((e["key"], e["first"], e["last"], e["worst"]) for e in expected),
          f"{where}: the page's episodes {got} are not the marks' runs of steps {expected}")
    check(len(got) < len(shown["violations"]), f"{where}: {len(got)} episodes for {len(shown['violations'])} marks: "
                                               "no violation was held over steps")
    items = page.evaluate("[...document.querySelectorAll('#violation-list li')].map((li) => li.textContent)")
    check(len(items) == min(50, len(got)), f"{where}: {len(items)} lines listed for {len(got)} episodes")
    held = [e for e in expected if e["last"] > e["first"]]
    check(any(f"steps {e['first']}-{e['last']}" in line and "at worst" in line for e in held for line in items),
          f"{where}: no line lists a held violation as 'steps FIRST-LAST': {items[:3]}")
    print(f"{where}: {len(shown['violations'])} violation marks listed as {len(got)} episodes, e.g. {items[0]!r}")


def watch_live(ctx, args, page, config, run_dir):
    ctx.start("launch", [args.dream, "launch", config, "--out", run_dir, "--pace", "3"])
    steps_seen, flash_shot = [], False
    deadline = time.monotonic() + 40
    while ctx.procs["launch"][0].poll() is None and time.monotonic() < deadline:
        shown = view_state(page)
        if shown and shown["step"] >= 0 and (not steps_seen or steps_seen[-1] != shown["step"]):
            steps_seen.append(shown["step"])
        if shown and shown["flashing"] > 0 and not flash_shot:
            page.screenshot(os.path.join(args.artifacts, "live.png"))  # a violation flashing
            flash_shot = True
        time.sleep(0.05)
    code = ctx.wait("launch", 5)
    check(code == 3, f"dream launch exited {code}; the config's run breaks the rules (expected 3, rejected)")
    # --pace 3: three times real time at most (a slower machine only goes slower).
    rate = read_summary(run_dir)["steps_per_second"]
    check(rate <= 3 / 0.033 * 1.05, f"dream launch --pace 3 ran {rate:.0f} steps/s, over three times real time")
    check(len(steps_seen) >= 5 and steps_seen == sorted(steps_seen),
          f"the page's step did not advance with the run: {steps_seen}")
    check(flash_shot, "no violation was flashing on the page at any time during the run")
    return steps_seen


def check_forged_run_after_the_end(dream, page, final, artifacts):
    """Issue 34: one DREAM_POSES of a made-up run after the end replaced the finished run on the
    page and wiped its violations. Now the finished run stays, and the page says another world
    is on the bus."""
    forged = dream.robot_poses_t()
    forged.step, forged.run_id, forged.num_robots = 0, FORGED_RUN_ID, 1
    forged.x, forged.y, forged.theta, forged.v, forged.w = [0.5], [0.5], [0.0], [0.0], [0.0]
    bus = Udpm()
    line_js = ("document.getElementById('other-world').hidden ? '' : "
               "document.getElementById('other-world').textContent")
    # Sent again until the page says it: the line goes 2 s after the other world's last message,
    # and a loaded machine may take longer than that to draw it.
    deadline, told, line = time.monotonic() + 10, None, ""
    while time.monotonic() < deadline and not (told and line):
        bus.publish("DREAM_POSES", forged.encode())
        time.sleep(0.1)
        shown = view_state(page)
        told = shown if shown and shown.get("otherWorld") else told
        line = page.evaluate(line_js) or line
    check(told is not None and line, f"the page never said another world is on the bus: {json.dumps(view_state(page))[:600]}")
    check(told["otherWorld"]["run"] == f"{FORGED_RUN_ID:016x}" and told["otherWorld"]["step"] == 0,
          f"the page names another world {told['otherWorld']}, not the forged run {FORGED_RUN_ID:016x} at step 0")
    check(told["run"] == final["run"] and told["step"] == STEPS and told["violations"] == final["violations"],
          f"a forged DREAM_POSES of another run changed the finished run drawn: run {told['run']} step "
          f"{told['step']}, {len(told['violations'])} violations (was run {final['run']} step {STEPS}, "
          f"{len(final['violations'])})")
    check(f"{FORGED_RUN_ID:016x}" in line, f"the status line says {line!r}, not the forged run")
    page.screenshot(os.path.join(artifacts, "other_world.png"))
    print(f"forged run after the end: the finished run stays drawn; the page says {line!r}")


def check_users_choice(dream, page):
    """The status line's button: the view draws the other run named there, from its next step."""
    other = dream.robot_poses_t()
    other.step, other.run_id, other.num_robots = 7, FORGED_RUN_ID, 1
    other.x, other.y, other.theta, other.v, other.w = [0.5], [0.5], [0.0], [0.0], [0.0]
    bus, clicked, shown = Udpm(), False, None
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        bus.publish("DREAM_POSES", other.encode())
        time.sleep(0.1)
        shown = view_state(page)
        if shown and shown["run"] == str(FORGED_RUN_ID):
            check(clicked, "the page drew the other run before the user chose it")
            check(shown["step"] == 7 and len(shown["robots"]) == 1 and not shown["violations"],
                  f"the run chosen is drawn at step {shown['step']} with {len(shown['robots'])} robots and "
                  f"{len(shown['violations'])} violations, not its step 7, one robot and none")
            print("the user's choice: the other run is drawn from its next step")
            return
        if shown and shown.get("otherWorld") and not clicked:
            page.evaluate("document.getElementById('follow-other').click()")
            clicked = True
    fail(f"the page never drew the run chosen with 'draw it instead' (clicked: {clicked}): {json.dumps(shown)[:600]}")


def goal_words(goal):
    """The start of summary.json's goal as the one judge words it (session::ExperimentGoal::Text)."""
    if goal.get("judge_error"):
        return "could not be judged"
    if not goal.get("has_criterion"):
        return goal.get("detail") or "none declared"
    return "met" if goal.get("met") else "missed"


def check_judged_live(page, summary, where):
    """Issue 33: a run watched live from another process ends on the world's DREAM_VERDICT, sent once
    summary.json is written: the page's data-verdict, its label and its goal line are summary.json's,
    not the counts' 'verdict so far'."""
    judged = wait_for_view(page, f"{where}: the world's verdict", lambda s: s["counts"] and s["counts"].get("judged"),
                      30)["counts"]["judged"]
    check(judged["verdict"] == summary["verdict"],
          f"{where}: the page ends on {judged['verdict']}, summary.json says {summary['verdict']}")
    check(judged["goal"].startswith(goal_words(summary["goal"])),
          f"{where}: the page's goal {judged['goal']!r}, summary.json's goal {summary['goal']}")
    check(judged["exit_code"] == 3, f"{where}: the verdict says exit code {judged['exit_code']}, dream launch exited 3")
    shown = wait_for_page(page, f"{where}: data-verdict and the label",
                          "[document.body.dataset.verdict, document.getElementById('verdict-label').textContent,"
                          " document.getElementById('goal').textContent]",
                          lambda v: v[0] == summary["verdict"] and v[1] == "verdict", 20)
    check(shown[2] == judged["goal"], f"{where}: the goal line says {shown[2]!r}, the verdict {judged['goal']!r}")
    print(f"{where}: ends on the judged verdict {shown[0]!r}, goal {shown[2]!r}")


def check_live_metrics(page, metrics):
    """Issue 37 item 3, a run of other processes (dream view --config beside dream launch): the
    kind's figure at the last step is summary.json's (it depends only on that step's poses), with
    the goal's tolerance as its threshold."""
    name = "final_max_goal_error_m"
    shown = wait_for_view(page, f"{name} plotted at the run's last step",
                     lambda s: any(m["name"] == name and m["step"] == STEPS for m in s.get("metrics") or []), 10)
    figure = next(m for m in shown["metrics"] if m["name"] == name)
    check(abs(figure["value"] - metrics[name]) <= 1e-6 * max(1.0, abs(metrics[name])),
          f"live, the page plots {name} = {figure['value']} at the last step, summary.json says {metrics[name]}")
    check(figure["threshold"] is not None, f"live, {name} has no threshold: {figure}")


def check_live(ctx, args, dream, page, config, run_dir):
    """dream launch watched live; then the same run's log played with lcm-logplayer. Returns its poses."""
    steps_seen = watch_live(ctx, args, page, config, run_dir)
    poses = poses_by_step(dream, os.path.join(run_dir, "run.lcmlog"))
    final = wait_for_view(page, f"the run's last step ({STEPS})", lambda s: s["step"] == STEPS, 30)
    check_robots(final, poses, "live")
    check_marks(final["violations"], poses, "live")
    check_episodes(page, final, "live")
    summary = read_summary(run_dir)["violations"]
    check(final["counts"]["boundary"] == summary["boundary_errors"] and
          final["counts"]["collision"] == summary["collision_errors"],
          f"the page's counts {final['counts']} are not summary.json's {summary}")
    check(final["verdict"] == "rejected", f"the page's verdict is {final['verdict']}, the run was rejected")
    check_judged_live(page, read_summary(run_dir), "live (dream launch)")
    check_live_metrics(page, read_summary(run_dir)["metrics"])
    print(f"live: {len(steps_seen)} steps seen, {len(final['violations'])} violations marked")
    check_forged_run_after_the_end(dream, page, final, args.artifacts)

    # A lab run, or any run log, watched by playing it on the bus.
    ctx.start("logplayer", ["lcm-logplayer", f"--lcm-url={os.environ['LCM_DEFAULT_URL']}", "-s", "4",
                            os.path.join(run_dir, "run.lcmlog")])
    wait_for_view(page, "the played log from its start", lambda s: s["step"] < STEPS / 2, 30)
    played = wait_for_view(page, "the played log to its end", lambda s: s["step"] == STEPS, 20)
    check_judged_live(page, read_summary(run_dir), "lcm-logplayer (the log's DREAM_VERDICT)")
    check_robots(played, poses, "lcm-logplayer")
    check_marks(played["violations"], poses, "lcm-logplayer")
    ctx.wait("logplayer", 10)
    check_users_choice(dream, page)
    return poses


def check_replay(ctx, args, page, run_dir, poses):
    """dream view RUN, its timeline driven as a user would."""
    ctx.start("replay", [args.dream, "view", run_dir, "--port", "0"])
    ctx.wait_for_output("replay", URL.pattern, 10)
    page.navigate(URL.search(ctx.output("replay")).group(1))
    shown = wait_for_view(page, "the replay loaded", lambda s: s["mode"] == "replay" and "replay" in s, 15)
    check(shown["replay"]["frames"] == STEPS + 1 and shown["step"] == 0,
          f"the replay starts at step {shown['step']} of {shown['replay']['frames']} frames; expected 0 of {STEPS + 1}")
    check(shown["violations"] == [] and shown["verdict"] == "clean", f"step 0 shows violations: {shown['violations']}")

    def click(element_id):
        page.evaluate(f"document.getElementById('{element_id}').click()")

    click("play")
    wait_for_view(page, "play advancing the timeline", lambda s: s["replay"]["playing"] and s["replay"]["index"] > 3, 30)
    click("play")  # pause
    paused = wait_for_view(page, "pause", lambda s: not s["replay"]["playing"], 20)
    time.sleep(0.3)
    check(view_state(page)["replay"]["index"] == paused["replay"]["index"], "the timeline moved while paused")
    click("step-forward")
    wait_for_view(page, "one step forward", lambda s: s["replay"]["index"] == paused["replay"]["index"] + 1, 20)
    click("step-back")
    wait_for_view(page, "one step back", lambda s: s["replay"]["index"] == paused["replay"]["index"], 20)
    page.evaluate("(() => { const s = document.getElementById('scrub'); s.value = '200';"
                  " s.dispatchEvent(new Event('input')); })()")
    scrubbed = wait_for_view(page, "the scrubbed step", lambda s: s["step"] == 200, 20)
    check_robots(scrubbed, poses, "replay at step 200")
    check_marks(scrubbed["violations"], poses, "replay at step 200")
    check(max(m["step"] for m in scrubbed["violations"]) <= 200, "the replay marks violations after its step")
    check_episodes(page, scrubbed, "replay at step 200")
    outside = sum(1 for step, p in poses.items() if step <= 200 and any(abs(x) > ARENA_X for x in p.x))
    check(scrubbed["counts"]["boundary"] == outside,
          f"at step 200 the page counts {scrubbed['counts']['boundary']} boundary errors, the log {outside}")
    check_inspection(page, poses, args.artifacts)
    page.evaluate("(() => { const s = document.getElementById('speed'); s.value = '4';"
                  " s.dispatchEvent(new Event('change')); })()")
    wait_for_view(page, "speed 4x", lambda s: s["replay"]["speed"] == 4, 20)
    page.screenshot(os.path.join(args.artifacts, "replay.png"))


def mouse(page, kind, x, y, **more):
    page.call("Input.dispatchMouseEvent", type=kind, x=x, y=y, **more)


def key(page, name, code):
    for kind in ("keyDown", "keyUp"):
        page.call("Input.dispatchKeyEvent", type=kind, key=name, code=code, text=name if len(name) == 1 else "")


def check_inspection(page, poses, artifacts):
    """Issue 37 item 2, with the browser's own mouse and keys: a robot clicked shows its pose,
    velocity and goal as the log has them; the wheel zooms about the cursor, f fits; the arrows
    step and space plays; Escape lets go; 50 robots get 50 colours."""
    colours = page.evaluate("new Set(Array.from({length: 50}, (_, i) => DreamArena.colour(i))).size")
    check(colours == 50, f"50 robots get {colours} distinct colours")
    at = page.evaluate("window.dreamView.pixelOf(1)")
    check(at is not None, "robot 1 has no place on the page")
    mouse(page, "mousePressed", at[0], at[1], button="left", clickCount=1)
    mouse(page, "mouseReleased", at[0], at[1], button="left", clickCount=1)
    shown = wait_for_view(page, "robot 1 picked by a click", lambda s: (s["selected"] or {}).get("id") == 1, 10)
    picked, truth = shown["selected"], poses[shown["step"]]
    check(abs(picked["x"] - truth.x[1]) < 1e-4 and abs(picked["y"] - truth.y[1]) < 1e-4,
          f"robot 1's details say ({picked['x']}, {picked['y']}), the log ({truth.x[1]:.4f}, {truth.y[1]:.4f})")
    check(abs(picked["v"] - truth.v[1]) < 1e-4 and abs(picked["w"] - truth.w[1]) < 1e-4,
          f"robot 1 drove ({picked['v']}, {picked['w']}) says the page, the log ({truth.v[1]}, {truth.w[1]})")
    goal_distance = ((-0.2 - truth.x[1]) ** 2 + (-0.5 - truth.y[1]) ** 2) ** 0.5
    check(picked["goals"]["count"] == 1 and (picked["goals"]["reached"] == 1) == (goal_distance <= 0.05),
          f"robot 1's goal (-0.2, -0.5), {goal_distance:.3f} m away: the page says {picked['goals']}")
    text = page.evaluate("document.getElementById('inspect').hidden ? '' : "
                         "document.getElementById('inspect-table').textContent")
    check(text.startswith("robot1") and f"({truth.x[1]:.3f}, {truth.y[1]:.3f}) m" in text,
          f"the side panel's robot details: {text!r}")
    page.evaluate("(() => { document.getElementById('show-velocities').checked = true; })()")
    mouse(page, "mouseWheel", at[0], at[1], deltaX=0, deltaY=-120)
    zoomed = wait_for_view(page, "the wheel zooming in", lambda s: s["camera"]["zoom"] > 1.1, 10)
    page.screenshot(os.path.join(artifacts, "inspect.png"))
    after = page.evaluate("window.dreamView.pixelOf(1)")
    check(abs(after[0] - at[0]) < 1.5 and abs(after[1] - at[1]) < 1.5,
          f"zooming about robot 1 (zoom {zoomed['camera']['zoom']:.2f}) moved it from {at} to {after}")
    key(page, "f", "KeyF")
    wait_for_view(page, "f fitting the arena again", lambda s: s["camera"]["zoom"] == 1, 10)
    index = shown["replay"]["index"]
    key(page, "ArrowRight", "ArrowRight")
    wait_for_view(page, "the right arrow stepping", lambda s: s["replay"]["index"] == index + 1, 10)
    key(page, " ", "Space")
    wait_for_view(page, "space playing", lambda s: s["replay"]["playing"], 10)
    key(page, " ", "Space")
    wait_for_view(page, "space pausing", lambda s: not s["replay"]["playing"], 10)
    key(page, "Escape", "Escape")
    wait_for_view(page, "Escape letting robot 1 go", lambda s: s["selected"] is None, 10)


def check_embedded(ctx, args, dream, page, config):
    """dream run --view, followed to its end, where the page becomes the run's replay with summary.json's verdict."""
    embedded_dir = ctx.path("embedded")
    ctx.start("embedded", [args.dream, "run", config, "--out", embedded_dir, "--view", "--view-port", "0",
                           "--pace", "4"])
    ctx.wait_for_output("embedded", URL.pattern, 10)
    page.navigate(URL.search(ctx.output("embedded")).group(1))
    ended = wait_for_view(page, "dream run --view to its end, replayed", lambda s: s["mode"] == "replay" and
                     s["step"] == STEPS and s.get("state") == "finished", 30)
    ctx.wait_for_output("embedded", r"a browser is watching: serving until Ctrl-C", 10)
    summary = read_summary(embedded_dir)
    check(ended["verdict"] == summary["verdict"],
          f"dream run --view ends the page on {ended['verdict']}, summary.json says {summary['verdict']}")
    shown = wait_for_page(page, "summary.json's verdict and goal in the side panel",
                          "[document.body.dataset.verdict, document.getElementById('goal').textContent]",
                          lambda v: v[0] == summary["verdict"] and v[1] != "-", 5)
    check(shown[1].startswith("met" if summary["goal"]["met"] else "missed") and
          summary["goal"]["detail"] in shown[1], f"the page's goal line '{shown[1]}', summary.json's {summary['goal']}")
    embedded_poses = poses_by_step(dream, os.path.join(embedded_dir, "run.lcmlog"))
    check_robots(ended, embedded_poses, "dream run --view")
    check_marks(ended["violations"], embedded_poses, "dream run --view")
    page.screenshot(os.path.join(args.artifacts, "run_view_end.png"))
    ctx.procs["embedded"][0].send_signal(signal.SIGINT)
    code = ctx.wait("embedded", 10)
    check(code == 3, f"dream run --view of a rejected run: exit {code} after Ctrl-C ended its page (expected 3)")
    wait_for_page(page, "the page keeping the replay after the server stopped",
                  "document.getElementById('connection').textContent",
                  lambda text: text.startswith("dream stopped serving"), 10)


def test(ctx):
    parser = argument_parser(types_dir=True)
    parser.add_argument("--artifacts", required=True, help="where the screenshots are kept")
    args = parser.parse_args()
    require_private_netns()
    dream = import_types(args.types_dir)
    os.makedirs(args.artifacts, exist_ok=True)
    config, run_dir = ctx.path("clash.yaml"), ctx.path("run")
    with open(config, "w") as f:
        f.write(CONFIG)

    ctx.start("view", [args.dream, "view", "--port", "0", "--config", config])
    ctx.wait_for_output("view", URL.pattern, 10)
    live_url = URL.search(ctx.output("view")).group(1)
    ctx.start("chromium", chromium_argv(ctx.path("chrome"), live_url), own_group=True)
    page = Page(devtools_port(ctx.path("chrome")))
    wait_for_view(page, "a connected live page", lambda s: s["connected"] and s["mode"] == "live", 20)

    poses = check_live(ctx, args, dream, page, config, run_dir)
    check_replay(ctx, args, page, run_dir, poses)
    check_embedded(ctx, args, dream, page, config)
    page.close()
    for shot in ("live.png", "replay.png"):
        path = os.path.join(args.artifacts, shot)
        check(os.path.getsize(path) > 10000, f"{path}: the screenshot is nearly empty")
    print(f"screenshots: {args.artifacts}/live.png, replay.png")


if __name__ == "__main__":
    main(test)
