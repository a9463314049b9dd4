#!/usr/bin/python3
"""sweep_cli: `dream sweep` runs an experiment over seeds and --set values, one `dream run` process
per run, and writes one folder per run plus sweep.csv and sweep.md; bad input is refused before
anything runs; Ctrl-C and runs that fail to run give the documented exit codes.

1. go_to_goal over seeds 1-3, --steps 40, --jobs 2: exit 0; one progress line per run; every run
   folder holds config.yaml (with its seed), run.lcmlog, summary.json (that seed, 40 steps),
   trajectories.png and output.txt; sweep.csv has the 3 rows in seed order and sweep.md says
   "3 ran" -- and no run is a success, since 40 steps are too few to arrive.
2. --set controller.max_speed_mps=0.1,0.15 for the whole run: both succeed, the slower arrives
   later, and each generated config holds its value.
3. Bad input, exit 1 with one line naming the culprit, and no sweep folder: unknown key, bad seed
   range, missing config, --out in a missing folder, a bad value (named with the base file's line),
   a misspelt new key; --jobs 0 is a usage error (2).
4. A run past --timeout is stopped and counts as failed to run: exit 4, the table says why.
5. SIGINT to the sweep stops its running children (exit 130); the table lists the interrupted
   runs and no run starts afterwards.

Usage: sweep_cli.py --dream BIN --source DIR
"""

import csv
import os
import re
import signal
import time

from dreamtest import arguments, check, main, read_summary

EXIT_INPUT = 1
EXIT_USAGE = 2
EXIT_RUN_FAILED = 4
EXIT_INTERRUPTED = 130


def read_csv(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def read_text(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path) as f:
        return f.read()


def small_sweep(ctx, dream, config):
    out = ctx.path("small")
    code, text = ctx.run([dream, "sweep", config, "--seeds", "1-3", "--steps", "40", "--jobs", "2", "--out", out],
                         timeout=60)
    check(code == 0, f"small sweep exited {code}: {text.strip()[-600:]}")
    progress = re.findall(r"^\[(\d)/3\] seed (\d): (.*), 40 steps$", text, re.MULTILINE)
    check(len(progress) == 3, f"expected 3 progress lines '[k/3] seed N: ..., 40 steps', got: {text.strip()[:600]}")
    check(sorted(p[0] for p in progress) == ["1", "2", "3"], f"progress counters: {progress}")
    for seed in (1, 2, 3):
        run = os.path.join(out, "runs", f"seed{seed}")
        for name in ("config.yaml", "run.lcmlog", "summary.json", "trajectories.png", "output.txt"):
            check(os.path.isfile(os.path.join(run, name)), f"{run}/{name} is missing")
        check(re.search(rf"^seed: {seed}$", read_text(os.path.join(run, "config.yaml")), re.MULTILINE),
              f"{run}/config.yaml does not say seed: {seed}")
        summary = read_summary(run)
        check(summary["seed"] == seed and summary["steps"] == 40 and summary["end"] == "finished",
              f"{run}/summary.json: seed {summary['seed']}, steps {summary['steps']}, end {summary['end']}")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check([r["seed"] for r in rows] == ["1", "2", "3"], f"sweep.csv seeds {[r['seed'] for r in rows]}")
    for row in rows:
        check(row["status"] == "ran" and row["steps"] == "40" and row["success"] == "false",
              f"sweep.csv row {row}")
        check(row["goal"].startswith("not all at their goals, worst"), f"sweep.csv goal column: {row['goal']!r}")
        check(float(row["min_distance_m"]) > 0.1, f"sweep.csv min distance {row['min_distance_m']}")
    md = read_text(os.path.join(out, "sweep.md"))
    check("| runs | 3 of 3 planned: 3 ran, 0 failed to run, 0 interrupted |" in md, f"sweep.md summary: {md[:800]}")
    check("| success rate | 0 of 3 (0.0 %) |" in md, "sweep.md success rate line")
    check(len(re.findall(r"^\| seed\d \| \d \| no success \| 40 \|", md, re.MULTILINE)) == 3,
          f"sweep.md should have 3 run rows: {md[-900:]}")
    check("| success rate |" in text, "the summary block is not printed at the end")
    # The run's config.yaml says how to run it again; that command works and gives the same run.
    run = os.path.join(out, "runs", "seed2")
    again = re.search(r"^# Run again \(replacing this run with the same one\): (dream run .*)$",
                      read_text(os.path.join(run, "config.yaml")), re.MULTILINE)
    check(again is not None, f"{run}/config.yaml has no 'Run again' line")
    before = read_summary(run)
    argv = again.group(1).split()
    code, text = ctx.run([dream] + argv[1:], timeout=60)
    # Exit 5, as the sweep's own run: 40 steps are too few to reach the goals.
    check(code == 5, f"the 'Run again' command exited {code}, expected 5: {text.strip()[-400:]}")
    after = read_summary(run)
    check((after["seed"], after["steps"], after["final_poses"]) == (before["seed"], before["steps"],
                                                                   before["final_poses"]),
          f"the run again differs: {after['final_poses']} vs {before['final_poses']}")
    return "3 seeds x 40 steps: 3 rows, 0 successes (as expected); a run's 'Run again' line repeats it"


def parameter_sweep(ctx, dream, config):
    out = ctx.path("speeds")
    code, text = ctx.run([dream, "-q", "sweep", config, "--seeds", "5", "--set", "controller.max_speed_mps=0.1,0.15",
                          "--out", out], timeout=60)
    check(code == 0, f"parameter sweep exited {code}: {text.strip()[-600:]}")
    check("[1/2]" not in text, "-q should hide the progress lines")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check([r["controller.max_speed_mps"] for r in rows] == ["0.1", "0.15"], f"parameter column: {rows}")
    check(all(r["success"] == "true" for r in rows), f"both speeds should succeed: {rows}")
    slow, fast = (int(r["completion_step"]) for r in rows)
    check(slow > fast > 0, f"completion steps: 0.1 m/s at {slow}, 0.15 m/s at {fast}")
    for row, speed in zip(rows, ("0.1", "0.15")):
        generated = read_text(os.path.join(out, "runs", row["run"], "config.yaml"))
        check(re.search(rf"^  max_speed_mps: {re.escape(speed)}$", generated, re.MULTILINE),
              f"runs/{row['run']}/config.yaml lacks max_speed_mps: {speed}")
    check("| success rate | 2 of 2 (100.0 %) |" in text, f"printed summary: {text[-800:]}")
    return f"2 speeds: both succeed, arrival at steps {slow} and {fast}"


def bad_inputs(ctx, dream, source, config):
    with open(config) as f:
        timeout_line = next(n for n, line in enumerate(f, 1) if line.startswith("  agent_timeout_s:"))
    missing_parent = ctx.path("no_such_folder", "sweep")
    cases = [
        (["--set", "controller.robot.max_speed_mps=0.1"], EXIT_INPUT,
         ["--set controller.robot.max_speed_mps", "no key 'robot' under controller", "keys there: kind"]),
        (["--seeds", "20-1"], EXIT_INPUT, ["--seeds 20-1", "runs backwards; write 1-20"]),
        (["--seeds", "1-x"], EXIT_INPUT, ["--seeds 1-x", "'1-x' is not a seed"]),
        (["--set", "world.agent_timeout_s=1,-1"], EXIT_INPUT,
         ["run seed1_agent_timeout_s--1 (seed 1, agent_timeout_s=-1)",
          f"go_to_goal.yaml:{timeout_line}: world.agent_timeout_s: must be > 0, got -1"]),
        (["--set", "controller.max_sped_mps=0.1"], EXIT_INPUT, ["controller.max_sped_mps", "unknown key"]),
        (["--set", "seed=1,2"], EXIT_INPUT, ["--set seed=1,2", "--seeds"]),
        (["--jobs", "0"], EXIT_USAGE, ["--jobs"]),
    ]
    for extra, expected, fragments in cases:
        out = ctx.path("bad")
        code, text = ctx.run([dream, "sweep", config, "--out", out] + extra, timeout=30)
        lines = text.strip().splitlines()
        check(code == expected, f"{' '.join(extra)}: exit {code}, expected {expected}: {text.strip()[:300]}")
        for fragment in fragments:
            check(fragment in lines[0], f"{' '.join(extra)}: first line lacks {fragment!r}: {lines[0]!r}")
        if expected == EXIT_INPUT:
            check(len(lines) == 1, f"{' '.join(extra)}: expected one line, got {len(lines)}: {text.strip()[:300]}")
        check(not os.path.exists(out), f"{' '.join(extra)}: the sweep folder was created")

    code, text = ctx.run([dream, "sweep", os.path.join(source, "config", "nope.yaml"), "--out", ctx.path("bad")])
    check(code == EXIT_INPUT and "nope.yaml: cannot open the config file" in text, f"missing config: {code} {text!r}")
    code, text = ctx.run([dream, "sweep", config, "--out", missing_parent])
    check(code == EXIT_INPUT and "its parent folder" in text and "does not exist" in text,
          f"--out in a missing folder: {code} {text!r}")
    check(not os.path.exists(os.path.dirname(missing_parent)), "the missing parent folder was created")
    return f"{len(cases) + 2} bad inputs refused"


def long_config(ctx, config):
    """go_to_goal that never ends by itself (every step runs)."""
    text = read_text(config)
    text, count = re.subn(r"^stop_when_done:\s*\S+", "stop_when_done: false", text, count=1, flags=re.MULTILINE)
    check(count == 1, "internal: no stop_when_done line")
    path = ctx.path("long.yaml")
    with open(path, "w") as f:
        f.write(text)
    return path


def timeout_fails(ctx, dream, config):
    out = ctx.path("timeout")
    code, text = ctx.run([dream, "sweep", long_config(ctx, config), "--steps", "100000000", "--timeout", "0.5",
                          "--out", out], timeout=60)
    check(code == EXIT_RUN_FAILED, f"a timed-out run: exit {code}, expected {EXIT_RUN_FAILED}: {text.strip()[-400:]}")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check(len(rows) == 1 and rows[0]["status"] == "failed" and rows[0]["problem"].startswith("timed out after"),
          f"sweep.csv of the timed-out run: {rows}")
    return "a run past --timeout: exit 4, 'timed out' in the table"


def interrupt(ctx, dream, config):
    out = ctx.path("interrupted")
    sweep = ctx.start("sweep", [dream, "sweep", long_config(ctx, config), "--seeds", "1-3", "--jobs", "2",
                                "--steps", "100000000", "--out", out])
    deadline = time.monotonic() + 20
    logs = [os.path.join(out, "runs", f"seed{s}", "run.lcmlog.part") for s in (1, 2)]
    while not all(os.path.exists(p) for p in logs):
        check(time.monotonic() < deadline and sweep.poll() is None,
              f"the first two runs did not start: {ctx.output('sweep')[-400:]}")
        time.sleep(0.05)
    time.sleep(0.3)
    sweep.send_signal(signal.SIGINT)
    code = ctx.wait("sweep", timeout=30)
    check(code == EXIT_INTERRUPTED, f"interrupted sweep exited {code}: {ctx.output('sweep')[-400:]}")
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check([(r["seed"], r["status"]) for r in rows] == [("1", "interrupted"), ("2", "interrupted")],
          f"sweep.csv of the interrupted sweep: {rows}")
    for seed in (1, 2):
        summary = read_summary(os.path.join(out, "runs", f"seed{seed}"))
        check(summary["end"] == "interrupted", f"seed {seed}: summary end {summary['end']}")
    check(not os.path.exists(os.path.join(out, "runs", "seed3")), "seed 3 started after the interruption")
    check("2 interrupted" in read_text(os.path.join(out, "sweep.md")), "sweep.md does not count the interrupted runs")
    return "SIGINT: exit 130, 2 interrupted rows, seed 3 never started"


def test(ctx):
    args = arguments()
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    print(small_sweep(ctx, args.dream, config))
    print(parameter_sweep(ctx, args.dream, config))
    print(bad_inputs(ctx, args.dream, args.source, config))
    print(timeout_fails(ctx, args.dream, config))
    print(interrupt(ctx, args.dream, config))


if __name__ == "__main__":
    main(test)
