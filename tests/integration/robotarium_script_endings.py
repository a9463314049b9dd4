#!/usr/bin/python3
"""robotarium_script_endings: how `dream run SCRIPT.py` ends (issue 36; docs/robotarium-scripts.md).

- A script path that is no file: one line, one "dream: " prefix, exit 1.
- A script that calls r.step() K times and then r.call_at_scripts_end(): the run takes K steps, as
  the official simulator counts them (its debug text's iterations are step() calls): summary.json
  steps, the log's last DREAM_POSES step and its one DREAM_VERDICT all say K; exit 0.
- A script that raises after K steps: the run ends there, judged as a run whose controller failed
  (summary.json end "finished", its reason naming the script's exception and line, the verdict's
  controller_failed reasons), exit 4 (session::ExitCodeOf: a controller failed), the traceback in
  script_output.txt.

Skipped (77) without numpy (DREAM's rps needs it).
Usage: netns.sh robotarium_script_endings.py --dream BIN --source DIR --types-dir DIR
"""

import os

from dreamtest import (check, check_log_ends_on_verdict, main, read_all, read_summary, run_script,
                       script_run_test_setup, tail)

STEPS = 25
FAIL_AFTER = 12

SCRIPT = """import numpy as np
import rps.robotarium as robotarium

r = robotarium.Robotarium(number_of_robots=2, show_figure=False, sim_in_real_time=False,
                          initial_conditions=np.array([[-0.5, 0.5], [0.0, 0.0], [0.0, 0.0]]))
for k in range({steps}):
    x = r.get_poses()
    if k == {fail_after}:
        raise ValueError("boom at step %d" % k)
    r.set_velocities(np.arange(2), np.array([[0.05, 0.05], [0.0, 0.0]]))
    r.step()
r.call_at_scripts_end()
"""
RAISE_LINE = 9  # the line of `raise` in SCRIPT


def write_script(ctx, name, fail_after):
    path = ctx.path(name + ".py")
    with open(path, "w") as f:
        f.write(SCRIPT.format(steps=STEPS, fail_after=fail_after))
    return path


def last_poses_step(dream_types, out_dir):
    poses = [event for event in read_all(os.path.join(out_dir, "run.lcmlog")) if event.channel == "DREAM_POSES"]
    return dream_types.robot_poses_t.decode(poses[-1].data).step


def test_missing_script(ctx, args):
    missing = ctx.path("no_such_script.py")
    code, output = ctx.run([args.dream, "run", missing])
    check(code == 1, f"dream run of a missing script exited {code}, expected 1: {tail(output)}")
    check(output.strip() == f"dream: {missing}: no such script (a Python file)",
          f"the missing script's error is not one line with one prefix: {output.strip()!r}")


def test_steps_are_the_scripts(ctx, args, dream_types):
    out_dir, code, output = run_script(ctx, args.dream, write_script(ctx, "ends", fail_after=-1), "ends")
    check(code == 0, f"the script's run exited {code}, expected 0: {tail(output, 1500)}")
    summary = read_summary(out_dir)
    check(summary["steps"] == STEPS, f"summary.json steps {summary['steps']}, the script called step() {STEPS} times")
    check(summary["end"] == "finished", f"summary.json end {summary['end']!r} ({summary['reason']})")
    step = last_poses_step(dream_types, out_dir)
    check(step == STEPS, f"the log's last DREAM_POSES is step {step}, expected {STEPS}")
    verdict = check_log_ends_on_verdict(dream_types, out_dir, code)
    check(verdict.step == STEPS, f"the log's verdict is of step {verdict.step}, expected {STEPS}")


def test_raising_script(ctx, args, dream_types):
    script = write_script(ctx, "raises", fail_after=FAIL_AFTER)
    out_dir, code, output = run_script(ctx, args.dream, script, "raises")
    check(code == 4, f"a script that raised exited {code}, expected 4 (a controller failed): {tail(output, 1500)}")
    summary = read_summary(out_dir)
    where = f"{script}:{RAISE_LINE}: ValueError: boom at step {FAIL_AFTER}"
    check(summary["end"] == "finished" and where in summary["reason"],
          f"summary.json end {summary['end']!r}, reason {summary['reason']!r}: expected the script's error {where!r}")
    check(summary["steps"] == FAIL_AFTER, f"the run took {summary['steps']} steps, the script {FAIL_AFTER}")
    rules = [reason["rule"] for reason in summary["verdict_reasons"]]
    check("controller_failed" in rules and "did_not_finish" not in rules,
          f"the verdict's reasons {rules} do not say the script (every robot's controller) failed")
    check(sorted(summary["robot_faults"]) == ["0", "1"], f"robot_faults {summary['robot_faults']}")
    check_log_ends_on_verdict(dream_types, out_dir, code)
    with open(os.path.join(out_dir, "script_output.txt"), errors="replace") as f:
        kept = f.read()
    check("Traceback (most recent call last)" in kept and f"ValueError: boom at step {FAIL_AFTER}" in kept,
          f"script_output.txt lacks the script's traceback: {tail(kept, 1500)}")


def test(ctx):
    args, dream_types = script_run_test_setup()
    test_missing_script(ctx, args)
    test_steps_are_the_scripts(ctx, args, dream_types)
    test_raising_script(ctx, args, dream_types)
    print(f"a missing script named once; {STEPS} step() calls are {STEPS} steps; a script raising at step "
          f"{FAIL_AFTER} ends the run there, exit 4, traceback kept")


if __name__ == "__main__":
    main(test)
