#!/usr/bin/python3
"""progress_display: `dream run` shows its progress as a bar redrawn in place on a terminal, as
plain lines when stderr is a file, and not at all with --quiet.

Three real-time runs at once (memq://, no network), long enough to show progress:
- on a terminal (`script` gives dream a pseudo-terminal; COLUMNS=60): '\\r'-redrawn lines with
  steps/s and ETA, none wider than 59 columns, redrawn at most ~10 times a second, and a newline
  after the last before the run's closing log line;
- stderr to a file: a plain "step k/N (p%), R steps/s, ETA m:ss" line after 2 s, no '\\r';
- on a terminal with --quiet: no progress.

Usage: progress_display.py --dream BIN --source DIR
"""

import os
import re
import shlex

from dreamtest import arguments, check, main

TTY_STEPS = 60     # 2 s of real time: the bar appears after 0.5 s
PLAIN_STEPS = 75   # 2.5 s: one plain line at 2 s


def test(ctx):
    args = arguments()
    config = os.path.join(args.source, "config", "go_to_goal.yaml")

    def run_argv(name, steps, quiet=False):
        return [args.dream] + (["-q"] if quiet else []) + ["run", config, "--mode", "realtime", "--steps",
                                                          str(steps), "--out", ctx.path(name)]

    env = dict(os.environ, COLUMNS="60")
    # script(1) runs the command on a pseudo-terminal; its stdin is not a terminal, so the
    # terminal has no size and dream falls back to $COLUMNS.
    ctx.start("tty", ["script", "-qec", shlex.join(run_argv("tty", TTY_STEPS)), "/dev/null"], env=env)
    ctx.start("quiet", ["script", "-qec", shlex.join(run_argv("quiet", TTY_STEPS, quiet=True)), "/dev/null"], env=env)
    ctx.start("plain", run_argv("plain", PLAIN_STEPS))
    for name in ("tty", "quiet", "plain"):
        check(ctx.wait(name, timeout=30) == 0, f"{name}: dream run failed: {ctx.output(name)[-400:]}")

    def raw_output(name):  # with its '\r's: ctx.output reads with universal newlines
        with open(ctx.procs[name][1], newline="", errors="replace") as f:
            return f.read().replace("\r\n", "\n")  # the terminal's own line ends

    tty = raw_output("tty")
    bar_pattern = re.compile(r"step (\d+)/%d( \[[#-]+\])?\s+\d+%%\s+\d+ steps/s\s+ETA \d+:\d\d" % TTY_STEPS)
    redraws = tty.split("\r")[1:]
    bars = [part.split("\n")[0].rstrip() for part in redraws if bar_pattern.match(part)]
    check(len(bars) >= 5, f"tty: {len(bars)} progress redraws, expected one every 0.1 s for 1.5 s: {tty[-400:]!r}")
    check(len(bars) <= 25, f"tty: {len(bars)} redraws in 2 s: not throttled to ~10 per second")
    too_wide = [bar for bar in bars if len(bar) > 59]
    check(not too_wide, f"tty: lines wider than COLUMNS - 1 = 59: {too_wide[:2]}")
    last_bar = redraws[-1]
    check(re.match(r"step %d/%d \[#+\]\s+100%%[^\n]*\n[^\n]*finished after %d steps" % ((TTY_STEPS,) * 3), last_bar),
          f"tty: the last redraw is not the full bar followed by a newline and the closing log line: "
          f"{last_bar[:200]!r}")

    quiet = raw_output("quiet")
    check("steps/s" not in quiet and "\r" not in quiet,
          f"--quiet on a terminal still shows progress: {quiet[-300:]!r}")

    plain = raw_output("plain")
    check("\r" not in plain, "plain: '\\r' in output that is not a terminal")
    lines = re.findall(r"^step (\d+)/%d \((\d+)%%\), (\d+) steps/s, ETA (\d+):(\d\d)$" % PLAIN_STEPS, plain, re.M)
    check(len(lines) >= 1, f"plain: no progress line in a 2.5 s run, expected one every 2 s: {plain[-500:]}")
    step, percent, rate, minutes, seconds = map(int, lines[0])
    check(50 <= step <= 70 and 20 <= rate <= 40, f"plain: at 2 s of a real-time run (30 steps/s): step {step}, "
                                                  f"{rate} steps/s")
    check(percent == 100 * step // PLAIN_STEPS or percent == round(100 * step / PLAIN_STEPS),
          f"plain: {percent}% for step {step} of {PLAIN_STEPS}")
    eta_s = 60 * minutes + seconds
    check(abs(eta_s - (PLAIN_STEPS - step) / rate) <= 1, f"plain: ETA {eta_s} s for {PLAIN_STEPS - step} steps "
                                                         f"at {rate} steps/s")
    print(f"tty: {len(bars)} redraws, last {bars[-1]!r}; plain: step {step}, {rate} steps/s, ETA {eta_s} s")


if __name__ == "__main__":
    main(test)
