#!/usr/bin/python3
"""interrupted_run_log_complete: Ctrl-C during a run leaves complete, readable outputs.

Starts `dream run` on a long copy of config/go_to_goal.yaml (100000 steps), once in real time (one
step per 33 ms; SIGINT after ~1 s, while the world waits for its next tick) and once in lockstep
(SIGINT after ~0.3 s, while it writes flat out), then in real time with SIGHUP (a closed terminal
or a dropped SSH session), and requires of each: exit code 130, summary.json
with end "interrupted", no run.lcmlog.part left behind, a log that `dream log info` accepts (it
fails on a truncated log) whose last DREAM_STATUS is ABORTED at the last DREAM_POSES step, and
that the Python reader reads every event the summary counts.

Usage: interrupted_run_log_complete.py --dream BIN --source DIR --types-dir DIR
"""

import os
import signal
import sys
import time

from dreamtest import TestFailure, arguments, check, config_with, main, read_summary

HERE = os.path.dirname(os.path.abspath(__file__))


def interrupt_run(ctx, args, mode, run_for_s, stop_signal=signal.SIGINT):
    """Runs the long config in `mode`, sends stop_signal after run_for_s seconds of running, checks
    the outputs; returns a one-line report."""
    signal_name = signal.Signals(stop_signal).name
    config = config_with(os.path.join(args.source, "config", "go_to_goal.yaml"), ctx.path(f"{mode}.yaml"),
                         steps=100000, stop_when_done=False, mode=mode)
    out = ctx.path(f"{mode}_{signal_name}")
    name = f"run_{mode}_{signal_name}"
    run = ctx.start(name, [args.dream, "run", config, "--out", out])
    ctx.wait_for_output(name, rf"running \({mode}\)", timeout=10)
    time.sleep(run_for_s)
    check(run.poll() is None, f"{mode}: dream run ended by itself ({run.returncode}) before the interruption")
    run.send_signal(stop_signal)
    code = ctx.wait(name, timeout=10)
    check(code == 130, f"{mode}: dream run exited {code} after {signal_name}, expected 130; output: "
                       f"{ctx.output(name).strip().splitlines()[-1]}")

    summary = read_summary(out)
    check(summary["end"] == "interrupted", f"{mode}: summary end is {summary['end']!r}, expected 'interrupted'")
    check(10 <= summary["steps"] < 100000, f"{mode}: summary steps {summary['steps']} after ~{run_for_s} s")
    check(not os.path.exists(os.path.join(out, "run.lcmlog.part")), f"{mode}: run.lcmlog.part left behind")
    log = os.path.join(out, "run.lcmlog")
    code, text = ctx.run([args.dream, "log", "info", log])
    check(code == 0, f"{mode}: dream log info refuses the interrupted log: {text.strip()}")
    check("DREAM_STATUS" in text, f"{mode}: dream log info lists no DREAM_STATUS: {text.strip()}")

    code, text = ctx.run([sys.executable, os.path.join(HERE, "..", "python", "check_python_types.py"),
                          "--types-dir", args.types_dir, "--log", log, "--summary", os.path.join(out, "summary.json"),
                          "--final-state", "ABORTED"], timeout=60)
    check(code == 0, f"{mode}: python reader on the interrupted log: {text.strip()}")
    return f"{mode}, {signal_name}: interrupted after {summary['steps']} steps; {text.strip()[:120]}"


def test(ctx):
    args = arguments(types_dir=True)
    # Real time: the signal arrives while the world waits for the next tick (the usual Ctrl-C).
    # Lockstep: it arrives while the world runs flat out, writing the log as fast as it can.
    failures = []
    # SIGHUP: the terminal closed or the SSH session dropped; the run ends as on Ctrl-C.
    for mode, run_for_s, stop_signal in [("realtime", 1.0, signal.SIGINT), ("lockstep", 0.3, signal.SIGINT),
                                         ("realtime", 0.5, signal.SIGHUP)]:
        try:
            print(interrupt_run(ctx, args, mode, run_for_s, stop_signal))
        except TestFailure as failure:
            failures.append(str(failure))
    check(not failures, "; ".join(failures))


if __name__ == "__main__":
    main(test)
