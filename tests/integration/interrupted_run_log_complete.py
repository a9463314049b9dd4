#!/usr/bin/python3
"""interrupted_run_log_complete: Ctrl-C during a run leaves complete, readable outputs.

Starts `dream run` on a long real-time copy of config/go_to_goal.yaml (100000 steps, one step per
33 ms), sends SIGINT once it has run for about a second, and requires: exit code 130, summary.json
with end "interrupted", no run.lcmlog.part left behind, a log that `dream log info` accepts (it
fails on a truncated log) and whose last DREAM_STATUS is ABORTED at the last DREAM_POSES step, and
that the Python reader reads every event the summary counts.

Usage: interrupted_run_log_complete.py --dream BIN --source DIR --types-dir DIR
"""

import argparse
import os
import signal
import subprocess
import sys
import time

from dreamtest import check, config_with, main, read_summary

HERE = os.path.dirname(os.path.abspath(__file__))


def test(ctx):
    parser = argparse.ArgumentParser()
    parser.add_argument("--dream", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--types-dir", required=True)
    args = parser.parse_args()

    config = config_with(os.path.join(args.source, "config", "go_to_goal.yaml"), ctx.path("long.yaml"),
                         steps=100000, stop_when_done=False, mode="realtime")
    out = ctx.path("run")
    run = ctx.start("run", [args.dream, "run", config, "--out", out])
    ctx.wait_for_output("run", r"running \(realtime\)", timeout=10)
    time.sleep(1.0)
    check(run.poll() is None, f"dream run ended by itself ({run.returncode}) before the interruption")
    run.send_signal(signal.SIGINT)
    code = ctx.wait("run", timeout=10)
    check(code == 130, f"dream run exited {code} after SIGINT, expected 130")

    summary = read_summary(out)
    check(summary["end"] == "interrupted", f"summary end is {summary['end']!r}, expected 'interrupted'")
    check(20 <= summary["steps"] < 100000,
          f"summary steps {summary['steps']}: a realtime run interrupted after ~1 s should have ~30")
    check(not os.path.exists(os.path.join(out, "run.lcmlog.part")), "run.lcmlog.part left behind")
    log = os.path.join(out, "run.lcmlog")
    code, text = ctx.run([args.dream, "log", "info", log])
    check(code == 0, f"dream log info refuses the interrupted log: {text.strip()}")
    check("DREAM_STATUS" in text, f"dream log info lists no DREAM_STATUS: {text.strip()}")

    code, text = ctx.run([sys.executable, os.path.join(HERE, "..", "python", "check_python_types.py"),
                          "--types-dir", args.types_dir, "--log", log, "--summary", os.path.join(out, "summary.json"),
                          "--final-state", "ABORTED"])
    check(code == 0, f"python reader on the interrupted log: {text.strip()}")
    print(f"interrupted after {summary['steps']} steps; {text.strip()}")


if __name__ == "__main__":
    main(test)
