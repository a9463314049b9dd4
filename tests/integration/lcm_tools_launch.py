#!/usr/bin/python3
"""lcm_tools_launch: `dream spy --log` and `dream replay --spy` start LCM's windows in the documented
order and end when the window that matters closes.

A window cannot open here, so stand-ins for `java` and `lcm-logplayer` on PATH note when they start,
with which arguments, and how they end. Checks, with DISPLAY set to a display that is never used:
- `dream spy --log RUN`: lcm-spy (java lcm.spy.Spy) first, the log player about 2 s later (so the
  spy has subscribed); closing the spy ends the command with exit 0 and ends the player; a spy that
  fails (exit 3) makes the command exit 4; Ctrl-C during the pause exits 130, ends the spy and starts
  no player.
- `dream replay RUN --spy`: `dream spy` on the same URL first, then LCM's log player (java
  lcm.logging.LogPlayer) once the spy has had time to start (they once started together and the
  spy missed the log's start); closing the player ends the command with exit 0 and ends the spy.

Usage: lcm_tools_launch.py --dream BIN --source DIR
"""

import os
import signal
import stat
import time

from dreamtest import argument_parser, check, main

FAKE_TOOL = """#!/bin/sh
# Stand-in for {name}: notes its start and arguments, then lives as the test says.
echo "start $(date +%s.%N) {name} $*" >> "$TOOLS_NOTES"
trap 'echo "term {name}" >> "$TOOLS_NOTES"; exit 143' TERM
case "$*" in
  *lcm.spy.Spy*) seconds="$SPY_SECONDS"; code="$SPY_EXIT" ;;
  *LogPlayer*) seconds="$PLAYER_SECONDS"; code=0 ;;
  *) seconds=60; code=0 ;;
esac
i=0
while [ "$i" -lt "$((seconds * 10))" ]; do sleep 0.1; i=$((i + 1)); done
echo "exit {name} $code" >> "$TOOLS_NOTES"
exit "$code"
"""


def write_tool(folder, name):
    path = os.path.join(folder, name)
    with open(path, "w", encoding="utf-8") as f:
        f.write(FAKE_TOOL.format(name=name))
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)


def notes(path):
    if not os.path.exists(path):
        return []
    with open(path, encoding="utf-8") as f:
        return [line.split() for line in f.read().splitlines()]


def started(lines, marker):
    """Start time of the first tool whose arguments hold `marker`."""
    for words in lines:
        if words[0] == "start" and marker in words:
            return float(words[1])
    return None


def wait_for_note(path, predicate, timeout):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if predicate(notes(path)):
            return True
        time.sleep(0.1)
    return False


def run_tools(ctx, name, argv, env, **tool_env):
    """Runs `argv` with the stand-ins living as `tool_env` says: (exit code, their notes, the notes file)."""
    notes_path = ctx.path(name + "_notes")
    ctx.start(name, argv, env=dict(env, TOOLS_NOTES=notes_path, **tool_env), own_group=True)
    code = ctx.wait(name, 30)
    return code, notes(notes_path), notes_path


def start_times(lines, what, player_marker):
    """When the spy and the player (the tool whose arguments hold `player_marker`) started."""
    spy_start = started(lines, "lcm.spy.Spy")
    player_start = started(lines, player_marker)
    check(spy_start is not None and player_start is not None, f"{what} did not start both tools: {lines}")
    return spy_start, player_start


def test(ctx):
    args = argument_parser().parse_args()
    run = ctx.path("run")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", run,
             "--steps", "5"], expect=0)
    tools = ctx.path("tools")
    os.makedirs(tools)
    for name in ("java", "lcm-logplayer"):
        write_tool(tools, name)
    env = dict(os.environ, PATH=tools + os.pathsep + os.environ["PATH"], DISPLAY=":99",
               LCM_DEFAULT_URL="udpm://239.255.76.67:7671?ttl=0", PLAYER_SECONDS="60")

    # dream spy --log: the spy, then the player 2 s later; the spy's window closing ends both.
    code, lines, spy_notes = run_tools(ctx, "spy", [args.dream, "spy", "--log", run], env,
                                       SPY_SECONDS="4", SPY_EXIT="0")
    check(code == 0, f"dream spy --log exited {code} when lcm-spy closed normally (expected 0): "
                     f"{ctx.output('spy').strip()[-300:]} notes {lines}")
    spy_start, player_start = start_times(lines, "dream spy --log", "lcm-logplayer")
    check(player_start - spy_start >= 1.8,
          f"the log player started {player_start - spy_start:.2f} s after lcm-spy; it must wait ~2 s for the spy")
    check(wait_for_note(spy_notes, lambda ls: ["term", "lcm-logplayer"] in ls, 5),
          f"the log player was not ended when lcm-spy closed: {notes(spy_notes)}")

    # A spy that fails fails the command.
    code, _, _ = run_tools(ctx, "failed_spy", [args.dream, "spy", "--log", run], env, SPY_SECONDS="3", SPY_EXIT="3")
    check(code == 4, f"dream spy exited {code} when lcm-spy failed with 3 (expected 4)")

    # Ctrl-C while the spy waits to subscribe: exit 130, and the player never starts.
    interrupted_notes = ctx.path("interrupted_notes")
    dream = ctx.start("interrupted", [args.dream, "spy", "--log", run],
                      env=dict(env, TOOLS_NOTES=interrupted_notes, SPY_SECONDS="60", SPY_EXIT="0"), own_group=True)
    check(wait_for_note(interrupted_notes, lambda ls: started(ls, "lcm.spy.Spy") is not None, 10),
          f"dream spy did not start lcm-spy: {ctx.output('interrupted')[-300:]}")
    dream.send_signal(signal.SIGINT)
    code = ctx.wait("interrupted", 30)
    time.sleep(2.5)  # past the pause: a player started after Ctrl-C would have noted itself by now
    lines = notes(interrupted_notes)
    check(code == 130, f"dream spy exited {code} on Ctrl-C (expected 130, interrupted)")
    check(started(lines, "lcm-logplayer") is None, f"the log player started after Ctrl-C: {lines}")
    check(["term", "java"] in lines, f"lcm-spy was not ended by Ctrl-C: {lines}")

    # dream replay --spy: dream spy on the same URL first, then the player; the player closing ends both.
    code, lines, replay_notes = run_tools(ctx, "replay", [args.dream, "replay", run, "--spy"], env,
                                          SPY_SECONDS="60", SPY_EXIT="0", PLAYER_SECONDS="4")
    check(code == 0, f"dream replay --spy exited {code} when the player closed normally (expected 0): "
                     f"{ctx.output('replay').strip()[-300:]} notes {lines}")
    spy_start, player_start = start_times(lines, "dream replay --spy", "lcm.logging.LogPlayer")
    check(player_start - spy_start >= 0.5,
          f"dream replay --spy started the player {player_start - spy_start:.2f} s after lcm-spy: the spy "
          f"misses the log's start (notes {lines})")
    spy_urls = [w for w in next(ws for ws in lines if "lcm.spy.Spy" in ws) if w.startswith("--lcm-url=")]
    player_words = next(ws for ws in lines if "lcm.logging.LogPlayer" in ws)
    player_url = player_words[player_words.index("--lcm-url") + 1]
    check(spy_urls == ["--lcm-url=" + player_url] and player_url.startswith(env["LCM_DEFAULT_URL"]),
          f"the spy of dream replay --spy listens on {spy_urls}, the player plays on {player_url}: "
          f"both should use $LCM_DEFAULT_URL {env['LCM_DEFAULT_URL']}")
    check(wait_for_note(replay_notes, lambda ls: ["term", "java"] in ls, 5),
          f"lcm-spy was not ended when the log player closed: {notes(replay_notes)}")
    print("dream spy and dream replay start and end LCM's windows in order")


if __name__ == "__main__":
    main(test)
