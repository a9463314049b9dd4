#!/usr/bin/python3
"""calibration_run: config/calibration.yaml, the calibration drive (issue 22 item 4).

1. Under `ideal` (the shipped config): the run ends when every robot reports done, at the
   program's last step (1480), clean: verdict clean, the goal met ("the program ran clean"),
   no boundary or collision error.
2. Under `--set world.realism=lab`: still clean, and `dream calibrate` on the run folder fits a
   lab model whose effective delays of steps from rest are within 25 % of the real robots'
   open-loop drives (issue 32: 635, 419 and 337 ms at 0.05, 0.1 and 0.19-0.2 m/s), and writes the
   realism file it names, which a run then uses (--set world.realism.file=...).

Usage: calibration_run.py --dream BIN --source DIR
"""

import os
import re

from dreamtest import arguments, check, main, read_summary

REAL_MEDIAN_DELAY_S = {0.05: 0.635, 0.10: 0.419, 0.19: 0.337}


def check_clean(run_dir):
    summary = read_summary(run_dir)
    check(summary["verdict"] == "clean", f"{run_dir}: verdict {summary['verdict']}: {summary.get('verdict_reasons')}")
    metrics = summary["metrics"]
    check(metrics["kind"] == "calibration_drive", f"{run_dir}: metrics.kind {metrics['kind']}")
    goal = metrics["goal"]
    check(goal["met"] and goal["completion_step"] == 1480 and goal["detail"] == "the program ran clean",
          f"{run_dir}: goal {goal}")
    check(metrics["boundary_error_steps"] == 0 and metrics["collision_steps"] == 0
          and metrics["calibration_last_step"] == 1480, f"{run_dir}: metrics {metrics}")
    return summary


def delays_of(report):
    """{speed: real delay s} from calibrate's table of steps from rest."""
    delays = {}
    for line in report.splitlines():
        match = re.match(r"\s+(\d+\.\d+)\s+(\d+)\s+(\d+) ms\s+(\d+) ms", line)
        if match:
            delays[float(match.group(1))] = float(match.group(3)) / 1000.0
    return delays


def test(ctx):
    args = arguments()
    config = os.path.join(args.source, "config", "calibration.yaml")

    # 1. ideal
    _, out = ctx.run([args.dream, "run", config, "--out", ctx.path("ideal")], timeout=60, expect=0)
    check("every robot reported done" in out and "finished after 1480 steps" in out,
          f"the ideal run did not end with the program: {out[-600:]}")
    check_clean(ctx.path("ideal"))

    # 2. lab, then calibrate
    ctx.run([args.dream, "run", config, "--set", "world.realism=lab", "--out", ctx.path("lab")], timeout=60, expect=0)
    check_clean(ctx.path("lab"))
    _, report = ctx.run([args.dream, "calibrate", ctx.path("lab"), "--out", ctx.path("mylab.yaml")], timeout=60,
                        expect=0)
    delays = delays_of(report)
    check(sorted(delays) == sorted(REAL_MEDIAN_DELAY_S), f"calibrate's step responses: {delays}\n{report[-1500:]}")
    for speed, real in REAL_MEDIAN_DELAY_S.items():
        check(abs(delays[speed] - real) <= 0.25 * real,
              f"effective delay at {speed} m/s: {delays[speed] * 1000:.0f} ms, the real robots' median "
              f"{real * 1000:.0f} ms (25 % allowed)")
    check(os.path.isfile(ctx.path("mylab.yaml")) and os.path.isfile(ctx.path("mylab.png")),
          "calibrate wrote no realism file or picture")
    ctx.run([args.dream, "run", config, "--set", "world.realism.file=" + ctx.path("mylab.yaml"), "--out",
             ctx.path("mylab_run")], timeout=60, expect=0)
    summary = check_clean(ctx.path("mylab_run"))
    check("realism" in summary, "the run on the fitted file has no realism section")
    print("effective delays under lab: " + ", ".join(f"{s} m/s {d * 1000:.0f} ms" for s, d in sorted(delays.items())))


if __name__ == "__main__":
    main(test)
