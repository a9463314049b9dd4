#!/usr/bin/python3
"""dream export --calibration end to end through the `dream` command (issue 22 item 4).

    calibration_export.py --dream build/dream --source . --simulator standin|official

1. Refusals, each one line with exit 1 and no folder made: --robots 0 and 21 (1 to 20), --robots
   without --calibration, --calibration without --robots, another --strategy, --barriers.
2. `dream export --calibration --robots 20` (the most the lab takes, the arena's fullest layout),
   run in a folder of its own: the run goes into runs/calibration_20 (clean, the program's goal
   met), the export into exports/calibration_20: the five replay files, export.json (replay,
   calibration), the program's commands step for step, and UPLOAD.txt saying how to import and
   calibrate.
3. `dream check-submission` of that export in the chosen simulator: the script runs clean (no
   debug() errors or warnings, complete), and `dream calibrate` accepts the folder it imported.

With --simulator official the checkout comes from $ROBOTARIUM_PYTHON_SIMULATOR; without it the
test prints SKIP and exits 77.
"""

import argparse
import json
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bridge_driver import check, drive, simulator_flags  # noqa: E402
from bridge_roundtrip import run  # noqa: E402

ROBOTS = 20
PROGRAM_STEPS = 1480
UPLOADS = ["dream_main.py", "dream_params.npy", "dream_initial_poses.npy", "dream_reference_poses.npy",
           "dream_reference_commands.npy"]


def refusals(dream, tmp):
    cwd = os.path.join(tmp, "refusals")
    os.makedirs(cwd)
    cases = [
        (["--calibration", "--robots", "0"], "--robots 0: the calibration drive runs 1 to 20 robots"),
        (["--calibration", "--robots", "21"], "--robots 21: the calibration drive runs 1 to 20 robots"),
        (["--robots", "3"], "--robots 3: goes with --calibration"),
        (["--calibration"], "pass --robots N with --calibration"),
        (["--calibration", "--robots", "3", "--strategy", "track"], "--strategy track: --calibration exports"),
        (["--calibration", "--robots", "3", "--barriers"], "--barriers: would change the program's commands"),
    ]
    # A run folder given as RUN and as --out: refused before any run.
    os.makedirs(os.path.join(cwd, "held"))
    with open(os.path.join(cwd, "held", "summary.json"), "w") as f:
        f.write("{}")
    cases += [
        (["--calibration", "--robots", "3", "--out", "held"], "--out held holds a run"),
        (["--calibration", "--robots", "3", "held"], "held: already holds a run"),
        (["--calibration", "--robots", "3", "same", "--out", "same"], "same is also --out"),
    ]
    for extra, message in cases:
        output, _ = run([dream, "export"] + extra, expect=1, cwd=cwd)
        check(message in output, "dream export %s: expected '%s', got: %s" % (" ".join(extra), message, output))
        check(os.listdir(cwd) == ["held"], "dream export %s left %s" % (" ".join(extra), os.listdir(cwd)))


def export(dream, tmp):
    cwd = os.path.join(tmp, "export")
    os.makedirs(cwd)
    output, seconds = run([dream, "export", "--calibration", "--robots", ROBOTS, "-q"], cwd=cwd)
    run_dir = os.path.join(cwd, "runs", "calibration_%d" % ROBOTS)
    export_dir = os.path.join(cwd, "exports", "calibration_%d" % ROBOTS)
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    check(summary["verdict"] == "clean", "the calibration run: verdict %s %s" % (summary["verdict"],
                                                                                summary.get("verdict_reasons")))
    check(summary["metrics"]["goal"]["met"], "the calibration run's goal: %s" % summary["metrics"]["goal"])
    check(sorted(os.listdir(os.path.join(export_dir, "upload"))) == sorted(UPLOADS),
          "upload/ holds %s" % sorted(os.listdir(os.path.join(export_dir, "upload"))))
    with open(os.path.join(export_dir, "export.json")) as f:
        manifest = json.load(f)
    check(manifest["strategy"] == "replay" and manifest.get("calibration") is True and manifest["robots"] == ROBOTS
          and manifest["steps"] == PROGRAM_STEPS, "export.json: %s" % manifest)
    with open(os.path.join(export_dir, "UPLOAD.txt")) as f:
        upload = f.read()
    for text in ["Number of robots to declare: %d" % ROBOTS, "It is the calibration drive",
                 "dream import dream_result.npy --export", "dream calibrate <lab run folder> --out mylab.yaml"]:
        check(text in upload, "UPLOAD.txt lacks '%s':\n%s" % (text, upload))
    check("dream calibrate" in output, "dream export --calibration did not print the instructions:\n" + output)
    # The program, open loop: every robot rests 61 steps, then drives 0.05 m/s for 91, rests 45, backs up.
    commands = np.load(os.path.join(export_dir, "upload", "dream_reference_commands.npy"), allow_pickle=False)
    check(commands.shape == (PROGRAM_STEPS, 2, ROBOTS), "reference commands of shape %s" % (commands.shape,))
    expected = {0: (0.0, 0.0), 60: (0.0, 0.0), 61: (0.05, 0.0), 151: (0.05, 0.0), 152: (0.0, 0.0),
                197: (-0.05, 0.0), PROGRAM_STEPS - 1: (0.0, 0.0)}
    for step, (v, w) in expected.items():
        check(np.all(commands[step, 0, :] == v) and np.all(commands[step, 1, :] == w),
              "step %d: commands %s, expected v %g w %g" % (step, commands[step], v, w))
    return export_dir, seconds


def check_submission(dream, tmp, export_dir, flags):
    check_dir = os.path.join(tmp, "check")
    output, seconds = run([dream, "check-submission", export_dir, "--out", check_dir, "-q"] + flags)
    with open(os.path.join(check_dir, "check.json")) as f:
        result = json.load(f)
    where = "check-submission (%s)" % result["simulator"]
    check(result["script_ok"], where + ": the script failed")
    check(result["verdict"] == "clean" and result["debug_verdict"] == "clean",
          where + ": verdict " + result["verdict"] + ", debug() " + result["debug_verdict"] + ":\n" + result["debug_text"])
    check(not result["python_warnings"], where + ": Python warnings: %s" % result["python_warnings"])
    check(result["complete"], where + ": the run did not complete")
    # What the lab would return, imported: what dream calibrate reads.
    report, _ = run([dream, "calibrate", check_dir, "--out", os.path.join(tmp, "fitted.yaml")])
    check("Lab model fitted to 1 run, %d robots" % ROBOTS in report, "dream calibrate on the check: " + report[-2000:])
    check(os.path.isfile(os.path.join(tmp, "fitted.yaml")), "dream calibrate wrote no realism file")
    # A simulator has no delay: a step from rest shows one step later (the official step), never
    # the seconds a simulator's fast clock (not real time) would make of it.
    delays = [float(m.group(1)) for m in re.finditer(r"^\s+\d\.\d\d\s+\d+\s+(-?\d+) ms", report, re.M)]
    check(len(delays) == 3 and all(-40 <= d <= 40 for d in delays), "effective delays in a simulator: %s\n%s" %
          (delays, report[-1500:]))
    check(re.search(r"step_overrun_mean_s\s+\S+\s+kept", report),
          "a simulator's clock was taken for the lab's:\n" + report[-3000:])
    return result, seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dream", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--simulator", choices=["standin", "official"], required=True)
    args = parser.parse_args()
    dream = os.path.abspath(args.dream)

    def body(tmp, report):
        flags, _ = simulator_flags(args.simulator, tmp, "to check the calibration export in it")
        if args.simulator == "standin":
            refusals(dream, tmp)
        export_dir, export_s = export(dream, tmp)
        result, check_s = check_submission(dream, tmp, export_dir, flags)
        report.append("export --calibration --robots %d: %.1f s; check-submission (%s): %.1f s, settle %d steps, "
                      "RMS %.2f cm from the simulated run" % (ROBOTS, export_s, result["simulator"], check_s,
                                                              result["settle_steps"],
                                                              100 * result.get("tracking_rms_m", 0)))
        return ""

    return drive("dream_calibration_export_", body)


if __name__ == "__main__":
    sys.exit(main())
