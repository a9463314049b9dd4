#!/usr/bin/python3
"""tutorial_python: docs/tutorial.md's Python part works as written.

Takes ring.py and ring.yaml from the tutorial's code blocks, then runs what it says: `dream
run ring.yaml` (every robot done, no collision, the verdict printed), the same run again gives
the same DREAM_POSES (`dream log diff`), the config mistake it quotes gives the error it quotes,
`dream export runs/ring --strategy controller` and `dream check-submission exports/ring`
(in DREAM's stand-in: exit 0, the script ended early because every robot was done, no
collision), whose summary.json and comparison.json judge the ring's own goal. The C++ part is the
install test's (tests/install/out_of_tree_controller.py).

Usage: tutorial_python.py --dream BIN --source DIR
"""

import csv
import json
import os
import re

from dreamtest import Context, arguments, check, main, read_summary


def code_blocks(text, language):
    return re.findall(r"```" + language + r"\n(.*?)```", text, flags=re.S)


def test(context, args):
    with open(os.path.join(args.source, "docs", "tutorial.md")) as f:
        tutorial = f.read()
    python = code_blocks(tutorial, "python")
    yaml = code_blocks(tutorial, "yaml")
    check(len(python) == 1 and len(yaml) == 1, "the tutorial should have one python and one yaml block")
    folder = context.path("experiment")
    os.makedirs(folder)
    for name, text in (("ring.py", python[0]), ("ring.yaml", yaml[0])):
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    os.chdir(folder)

    code, output = context.run([args.dream, "run", "ring.yaml"], timeout=120)
    check(code == 0 and "No errors or warnings" in output, f"dream run ring.yaml: exit {code}: {output[-300:]}")
    summary = read_summary("runs/ring")
    check(summary["robots_done"] == list(range(6)), f"not every robot arrived: {summary['robots_done']}")
    check(summary["violations"]["collision_errors"] == 0, f"collisions: {summary['violations']}")
    check(500 <= summary["steps"] <= 900, f"the tutorial says about 680 steps, the run took {summary['steps']}")
    # The ring's own goal (its goal_points, metrics and goal classmethods), judged from the log.
    goal = summary["goal"]
    check(goal["has_criterion"] and goal["met"] and goal["detail"].startswith("ring formed, worst")
          and 0 < goal["completion_step"] <= summary["steps"], f"the ring's goal in summary.json: {goal}")
    check(len(summary["metrics"]["goal_points"]) == 6 and len(summary["metrics"]["final_error_m"]) == 6,
          f"the ring's goal points and figures: {summary['metrics']}")

    context.run([args.dream, "run", "ring.yaml", "--out", "again", "-q"], timeout=120, expect=0)
    code, output = context.run([args.dream, "log", "diff", "runs/ring/run.lcmlog", "again/run.lcmlog", "--channels",
                                "DREAM_POSES"], timeout=60)
    check(code == 0 and output.startswith("same"), f"two runs differ: {output[-300:]}")

    quoted = re.search(r"`radius_m: 2`, stops the run before it starts with `([^`]*)`", tutorial.replace("\n", " "))
    check(quoted is not None, "the tutorial no longer quotes the radius_m mistake")
    with open("ring.yaml") as f:
        text = f.read()
    with open("ring.yaml", "w") as f:
        f.write(text.replace("radius_m: 0.6", "radius_m: 2"))
    code, output = context.run([args.dream, "run", "ring.yaml", "--out", "bad"], timeout=60)
    check(code == 1 and quoted.group(1) in output, f"expected '{quoted.group(1)}', got exit {code}: {output[-300:]}")
    with open("ring.yaml", "w") as f:
        f.write(text)

    # The tutorial's sweep: success means the ring formed; robots too slow to reach it in the
    # config's 2000 steps never form it.
    code, output = context.run([args.dream, "-q", "sweep", "ring.yaml", "--seeds", "1", "--set",
                                "controller.speed_mps=0.15,0.01"], timeout=300)
    with open(os.path.join("sweeps", "ring", "sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    check([(r["success"], r["goal"].split(",")[0].split(":")[0]) for r in rows] == [("true", "ring formed"),
                                                                                      ("false", "no ring")],
          f"the ring's sweep (exit {code}): {[(r['success'], r['goal']) for r in rows]}")

    context.run([args.dream, "export", "runs/ring", "--strategy", "controller"], timeout=120, expect=0)
    check(os.path.isfile("exports/ring/upload/ring.py") and os.path.isfile("exports/ring/upload/dream_main.py"),
          "the export lacks ring.py or dream_main.py")
    code, output = context.run([args.dream, "check-submission", "exports/ring", "--standin"], timeout=300)
    check(code == 0, f"dream check-submission exited {code}: {output[-400:]}")
    check("debug()'s real seconds are the time on the lab's robots" in output,
          f"check-submission does not say debug()'s seconds are the lab's: {output[-400:]}")
    # The script ends early only when every robot reports done.
    lab = read_summary("runs/ring_check")
    check(lab["lab"]["complete"] and lab["steps"] < lab["lab"]["planned_steps"],
          f"in the submission not every robot arrived: {lab['steps']} of {lab['lab']['planned_steps']} steps")
    check(lab["violations"]["collision_errors"] == 0, f"collisions in the submission: {lab['violations']}")
    # The ring's own goal, judged on the lab's poses by the import and by the comparison.
    check(lab.get("goal", {}).get("met") is True and lab["metrics"].get("goal_points"),
          f"the check's summary.json lacks the ring's own goal: {lab.get('goal')}, {lab['metrics']}")
    with open(os.path.join("runs", "ring_check", "comparison.json")) as f:
        compared = json.load(f)
    for side in ("first", "second"):
        check(compared[side]["metrics"].get("goal", {}).get("met") is True,
              f"comparison.json's {side} run lacks the ring's goal: {compared[side]['metrics']}")


if __name__ == "__main__":
    main(lambda context: test(context, arguments()))
