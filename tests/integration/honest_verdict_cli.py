#!/usr/bin/python3
"""honest_verdict_cli: a run that went wrong says so in its verdict, exit code, printed report and
summary.json, and dream export refuses it (unless --force), naming each reason.

1. go_to_goal as shipped: exit 0, verdict clean, no reasons, debug()'s text word for word.
2. go_to_goal with `steps: 40` in its config (the robots cannot arrive): exit 5, verdict not_ready
   with the reason `goal`, the printed report says NOT ready and never "will run on the Robotarium";
   `dream export` exits 3 naming `goal`, writes nothing; `--force` exports with a WARNING.
3. the shipped config with `--steps 40`: the goal is not judged (the run was cut on purpose): exit 0,
   "judged": false, and one line says so.
4. two robots with goals outside the arena: debug() counts 95 steps with a robot outside, the lab's
   verifier 180 robot-steps (over its 100): exit 3, reasons `boundary` and `verifier_out_of_bounds`.

Usage: honest_verdict_cli.py --dream BIN --source DIR
"""

import json
import os

from dreamtest import argument_parser, check, main


def summary_of(run):
    with open(os.path.join(run, "summary.json")) as f:
        return json.load(f)


def rules(summary):
    return [reason["rule"] for reason in summary["verdict_reasons"]]


def config_with(ctx, source, name, replacements):
    with open(os.path.join(source, "config", "go_to_goal.yaml")) as f:
        text = f.read()
    for old, new in replacements:
        check(old in text, f"config/go_to_goal.yaml no longer holds {old!r}; update this test")
        text = text.replace(old, new)
    path = ctx.path(name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    return path


def test(ctx):
    args = argument_parser().parse_args()
    dream = args.dream
    shipped = os.path.join(args.source, "config", "go_to_goal.yaml")

    clean = ctx.path("clean")
    code, text = ctx.run([dream, "run", shipped, "--out", clean], timeout=60, expect=0)
    summary = summary_of(clean)
    check(summary["verdict"] == "clean" and summary["verdict_reasons"] == [] and summary["goal"]["met"],
          f"the shipped go_to_goal should be clean with its goal met: {summary['verdict']} {summary['verdict_reasons']}")
    check(summary["robotarium_report"] in text, f"a clean run prints debug()'s text as is: {text[:300]}")
    # -q keeps only warnings and errors: a clean run whose goal was met prints nothing.
    code, text = ctx.run([dream, "-q", "run", shipped, "--out", clean, "--overwrite"], timeout=60, expect=0)
    check(text == "", f"dream -q run of a clean run printed more than warnings and errors: {text.strip()[-300:]}")

    short = config_with(ctx, args.source, "short", [("steps: 1500", "steps: 40")])
    missed = ctx.path("missed")
    code, text = ctx.run([dream, "-q", "run", short, "--out", missed], timeout=60, expect=5)
    summary = summary_of(missed)
    check(summary["verdict"] == "not_ready" and rules(summary) == ["goal"],
          f"a run that misses its goal: verdict {summary['verdict']}, reasons {rules(summary)}")
    check(summary["robotarium_verdict"] == "clean", f"its poses are still clean: {summary['robotarium_verdict']}")
    check(summary["goal"]["judged"] and not summary["goal"]["met"], f"goal: {summary['goal']}")
    check("will run on the Robotarium" not in text and "NOT ready for the Robotarium" in text
          and "goal: the go_to_goal experiment missed its goal" in text,
          f"the printed report must say what is wrong and never 'will run': {text[:600]}")

    refused = ctx.path("refused_export")
    code, text = ctx.run([dream, "export", missed, "--out", refused], timeout=30, expect=3)
    check("goal: the go_to_goal experiment missed its goal" in text and "--force" in text,
          f"dream export should name the reason and --force: {text[-500:]}")
    check(not os.path.exists(refused), "a refused export wrote its folder")
    forced = ctx.path("forced_export")
    code, text = ctx.run([dream, "export", missed, "--out", forced, "--force"], timeout=30, expect=0)
    with open(os.path.join(forced, "UPLOAD.txt")) as f:
        upload = f.read()
    check("WARNING: goal:" in upload and "exported anyway: --force" in upload,
          f"UPLOAD.txt of a forced export should carry the reason as a warning: {upload[-400:]}")

    cut = ctx.path("cut")
    code, text = ctx.run([dream, "-q", "run", shipped, "--out", cut, "--steps", "40"], timeout=60, expect=0)
    summary = summary_of(cut)
    check(summary["verdict"] == "clean" and not summary["goal"]["judged"],
          f"--steps 40: the goal is not judged: {summary['verdict']} {summary['goal']}")
    check("goal: not judged, --steps 40 stopped the run first" in text, f"say the goal was not judged: {text[:400]}")

    outside = config_with(ctx, args.source, "outside",
                          [("- [0.416, 0.134]", "- [1.75, 0.134]"), ("- [0.416, -0.134]", "- [1.75, -0.334]")])
    out_run = ctx.path("outside_run")
    code, text = ctx.run([dream, "-q", "run", outside, "--out", out_run], timeout=60, expect=3)
    summary = summary_of(out_run)
    check(rules(summary)[:2] == ["boundary", "verifier_out_of_bounds"] and summary["verdict"] == "rejected",
          f"robots outside: reasons {rules(summary)}, verdict {summary['verdict']}")
    steps_outside = summary["violations"]["boundary_errors"]
    verifier = next(r for r in summary["verdict_reasons"] if r["rule"] == "verifier_out_of_bounds")
    check(f"{steps_outside} time steps where robots were outside boundaries" in text
          and "times (robots x steps)" in verifier["problem"] and "Also:" in text,
          f"debug()'s count and the verifier's both shown: {text[:700]}")
    print(f"outside: debug() {steps_outside} steps; verifier: {verifier['problem']}")

    # Where and when (issue 25 item 3): robots 0 and 7 drive out past the right
    # wall; summary.json places each, and the picture and dream render mark them.
    located = summary["violations_located"]
    outside_robots = sorted(e["robots"][0] for e in located["listed"] if e["kind"] == "boundary")
    check(outside_robots == [0, 7] and located["unlisted"] == 0,
          f"violations_located should list robots 0 and 7 outside: {located}")
    for entry in located["listed"]:
        check(entry["kind"] != "boundary" or (entry["position"][0] > 1.6 and 0 < entry["first_step"] <= entry["last_step"]),
              f"a robot outside is placed past the right wall (x > 1.6) with its steps: {entry}")
    boundary = next(r for r in summary["verdict_reasons"] if r["rule"] == "boundary")
    check("violations_located says where and when" in boundary["find_out"] and "dream render RUN" in boundary["find_out"],
          f"the boundary reason should say where to look: {boundary}")
    marked = os.path.join(out_run, "marked.png")
    code, text = ctx.run([dream, "render", out_run, "--out", marked], timeout=60, expect=0)
    check(os.path.getsize(marked) > 0, "dream render drew no picture")


if __name__ == "__main__":
    main(test)
