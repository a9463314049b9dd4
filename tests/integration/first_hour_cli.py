#!/usr/bin/python3
"""first_hour_cli: the options a new user reaches for first (issue 12, "the first hour").

1. `dream --version` and `dream version` print one line: CMake's PROJECT_VERSION (and the git commit).
2. `dream run --seed N` changes the generated start poses; config.yaml records the seed and --set
   values, and rerunning that config.yaml alone gives the same poses. --set mistakes name the key,
   exit 1 and create no folder.
3. A rerun never overwrites: without --out the second run goes to runs/<name>_2 (said in one line),
   an --out holding a run is refused naming it and --overwrite, --overwrite replaces it. The README's
   main command (`dream run config/go_to_goal.yaml`) works twice in a row.
4. `dream sweep` without --out writes sweeps/<name>, and a second sweep sweeps/<name>_2.
5. `dream log echo` prints one JSON object per message, equal to the log read by python/dream_log.py
   and the generated Python types (radio payloads as hex); an undecodable event is reported with its
   byte offset and the rest still printed; channels of no DREAM type are skipped and counted.

Usage: first_hour_cli.py --dream BIN --source DIR --types-dir DIR
"""

import json
import os
import re
import struct
import subprocess

from dreamtest import arguments, check, import_types, main, read_events, read_summary

EXIT_INPUT = 1
EXIT_USAGE = 2


def run_in(cwd, argv, timeout=60):
    """Runs argv in folder cwd; returns (exit code, stdout+stderr)."""
    result = subprocess.run(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=timeout, stdin=subprocess.DEVNULL)
    return result.returncode, result.stdout


def first_poses(dream_types, run_dir):
    for event in read_events(os.path.join(run_dir, "run.lcmlog")):
        if event.channel == "DREAM_POSES":
            poses = dream_types.robot_poses_t.decode(event.data)
            return list(zip(poses.x, poses.y, poses.theta))
    check(False, f"{run_dir}: no DREAM_POSES")


def version(ctx, args):
    code, text = ctx.run([args.dream, "--version"], expect=0)
    code2, text2 = ctx.run([args.dream, "version"], expect=0)
    with open(os.path.join(args.source, "CMakeLists.txt")) as f:
        project_version = re.search(r"project\(dream VERSION (\S+)", f.read()).group(1)
    check(re.fullmatch(r"dream " + re.escape(project_version) + r"( \(git [0-9a-f]{7,40}\))?\n", text),
          f"dream --version printed {text!r}, expected 'dream {project_version} (git <commit>)'")
    check(text2 == text, f"dream version printed {text2!r}, dream --version {text!r}")
    return f"--version: {text.strip()}"


def seed_and_set(ctx, args, dream_types):
    config = os.path.join(args.source, "config", "hrvo_circle.yaml")  # poses generated from the seed
    a, b, again = ctx.path("seed2"), ctx.path("seed3"), ctx.path("seed3_again")
    common = ["--steps", "3", "--all-steps"]
    ctx.run([args.dream, "-q", "run", config, "--out", a, "--seed", "2"] + common, expect=0)
    ctx.run([args.dream, "-q", "run", config, "--out", b, "--seed", "3", "--set", "controller.max_speed_mps=0.12"]
            + common, expect=0)
    check(first_poses(dream_types, a) != first_poses(dream_types, b), "--seed 2 and --seed 3 gave the same poses")
    check(read_summary(b)["seed"] == 3, f"summary.json: seed {read_summary(b)['seed']}, expected 3")
    with open(os.path.join(b, "config.yaml")) as f:
        recorded = f.read()
    check(re.search(r"^seed: 3$", recorded, re.MULTILINE), f"config.yaml does not record seed: 3:\n{recorded[:400]}")
    check(re.search(r"^  max_speed_mps: 0\.12$", recorded, re.MULTILINE),
          "config.yaml does not record controller.max_speed_mps: 0.12")
    check("--seed 3 --set controller.max_speed_mps=0.12" in recorded.splitlines()[0],
          f"config.yaml's first line does not name the overrides: {recorded.splitlines()[0]}")
    # The folder alone reruns the run.
    ctx.run([args.dream, "-q", "run", os.path.join(b, "config.yaml"), "--out", again] + common, expect=0)
    # Every channel, commands and DREAM_APPLIED too: log diff ignores run and agent ids, random per run and process.
    code, text = ctx.run([args.dream, "log", "diff", b, again])
    check(code == 0 and "same" in text, f"rerunning {b}/config.yaml gave another log: {text.strip()}")
    # Two seeds differ: exit 1 (as diff(1)) and where first: channel, step, robot, field.
    code, text = ctx.run([args.dream, "log", "diff", a, b, "--channels", "DREAM_POSES"])
    check(code == 1 and re.search(r"DREAM_POSES: message \d+ differs first at step \d+, robot \d+: \w+ ", text),
          f"log diff of --seed 2 and --seed 3: exit {code}, expected 1 and where they differ: {text.strip()}")
    code, text = ctx.run([args.dream, "log", "info", a])
    check(code == 0 and re.search(r": \d+ events, \d+\.\d\d s of log time\n", text),
          f"dream log info: exit {code}, expected its duration to 0.01 s: {text.strip()[:300]}")
    code, text = ctx.run([args.dream, "log", "diff", a, ctx.path("no_such_run")])
    check(code == 2 and "no_such_run" in text,
          f"log diff with a missing run: exit {code}, expected 2 (not compared) naming it: {text.strip()}")

    bad = ctx.path("bad")
    cases = [
        (["--set", "controller.max_sped=0.1"], EXIT_INPUT, ["controller.max_sped", "--set controller.max_sped=0.1"]),
        (["--set", "controller.max_speed_mps=fast"], EXIT_INPUT,
         ["controller.max_speed_mps", "'fast'", "--set controller.max_speed_mps=fast"]),
        (["--set", "contrler.gain=1"], EXIT_INPUT, ["--set contrler.gain", "no key 'contrler'"]),
        (["--set", "controller.max_speed_mps"], EXIT_USAGE, ["--set", "KEY=VALUE", "got controller.max_speed_mps"]),
        (["--set", "controller.max_speed_mps=0.1,0.2"], EXIT_INPUT, ["one value per key", "dream sweep"]),
        (["--seed", "4", "--set", "seed=5"], EXIT_INPUT, ["--set seed=5", "--seed"]),
        (["--seed", "-1"], EXIT_USAGE, ["--seed", "-1"]),
        (["--seed", "x"], EXIT_USAGE, ["--seed", "x"]),
    ]
    for extra, expected, needles in cases:
        code, text = ctx.run([args.dream, "run", config, "--out", bad] + extra)
        check(code == expected, f"{' '.join(extra)}: exit {code}, expected {expected}: {text.strip()}")
        for needle in needles:
            check(needle in text, f"{' '.join(extra)}: message lacks {needle!r}: {text.strip()}")
        check(not os.path.exists(bad), f"{' '.join(extra)}: the output folder was created")
    return f"--seed/--set: poses differ by seed, config.yaml records them and reruns alone; {len(cases)} mistakes named"


def reruns(ctx, args):
    cwd = ctx.path("fresh")
    os.mkdir(cwd)
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    # The README's main command, twice in a row, then once more.
    for expected in ("go_to_goal", "go_to_goal_2", "go_to_goal_3"):
        code, text = run_in(cwd, [args.dream, "run", config])
        check(code == 0, f"dream run (-> runs/{expected}) exited {code}: {text.strip()[-300:]}")
        check(os.path.isfile(os.path.join(cwd, "runs", expected, "summary.json")), f"runs/{expected} has no summary")
        if expected != "go_to_goal":
            lines = [line for line in text.splitlines() if "holds an earlier run" in line]
            check(len(lines) == 1 and f"runs/{expected}" in lines[0],
                  f"the rerun did not say it writes runs/{expected}: {text.strip()[:400]}")
    first = os.path.join(cwd, "runs", "go_to_goal")
    before = os.stat(os.path.join(first, "run.lcmlog"))
    code, text = run_in(cwd, [args.dream, "run", config, "--out", "runs/go_to_goal", "--steps", "5"])
    check(code == EXIT_INPUT, f"--out holding a run: exit {code}, expected {EXIT_INPUT}: {text.strip()}")
    for needle in ("runs/go_to_goal", "already holds a run", "--overwrite", "another --out"):
        check(needle in text, f"--out refusal lacks {needle!r}: {text.strip()}")
    after = os.stat(os.path.join(first, "run.lcmlog"))
    check((before.st_size, before.st_mtime_ns) == (after.st_size, after.st_mtime_ns), "the refused run touched the log")
    # What commands on the earlier run left beside it (a video, a plot, a comparison) goes too.
    left = ["run.mp4", "metrics.png", "comparison.json", "check.json"]
    for name in left:
        with open(os.path.join(first, name), "w") as f:
            f.write("the earlier run's")
    code, text = run_in(cwd, [args.dream, "-q", "run", config, "--out", "runs/go_to_goal", "--steps", "5",
                                   "--all-steps", "--overwrite"])
    check(code == 0, f"--overwrite exited {code}: {text.strip()}")
    check(read_summary(first)["steps"] == 5, "--overwrite did not replace the summary")
    kept = [name for name in left if os.path.exists(os.path.join(first, name))]
    check(not kept, f"--overwrite kept the earlier run's {kept}")
    check(not os.path.exists(os.path.join(cwd, "runs", "go_to_goal_4")), "--overwrite wrote a new folder")
    return "reruns: runs/go_to_goal, _2, _3; --out refused naming --overwrite; --overwrite replaces, outputs and all"


def sweep_default(ctx, args):
    cwd = ctx.path("sweeping")
    os.mkdir(cwd)
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    for expected in ("go_to_goal", "go_to_goal_2"):
        code, text = run_in(cwd, [args.dream, "sweep", config, "--seeds", "1-2", "--steps", "5", "--jobs", "2"],
                            timeout=90)
        check(code == 0, f"dream sweep without --out exited {code}: {text.strip()[-400:]}")
        folder = os.path.join(cwd, "sweeps", expected)
        check(os.path.isfile(os.path.join(folder, "sweep.csv")), f"sweeps/{expected}/sweep.csv is missing")
        with open(os.path.join(folder, "sweep.md")) as f:
            check(f"--out sweeps/{expected}" in f.read(), f"sweeps/{expected}/sweep.md: command lacks its folder")
    return "sweep: sweeps/go_to_goal, then sweeps/go_to_goal_2"


def lcm_event(number, utime, channel, data):
    return struct.pack(">IqqII", 0xEDA1DA01, number, utime, len(channel), len(data)) + channel.encode() + data


def log_echo(ctx, args, dream_types):
    run = ctx.path("radio")
    config = os.path.join(args.source, "config", "hrvo_circle.yaml")  # radio every 30 steps
    ctx.run([args.dream, "-q", "run", config, "--out", run, "--steps", "60", "--all-steps"], expect=0)
    log = os.path.join(run, "run.lcmlog")
    code, text = ctx.run([args.dream, "log", "echo", run, ".*"], expect=0)
    lines = [json.loads(line) for line in text.splitlines() if line.startswith("{")]
    events = list(read_events(log))
    check(len(lines) == len(events), f"log echo printed {len(lines)} messages, the log has {len(events)} events")
    types = {"DREAM_POSES": dream_types.robot_poses_t, "DREAM_STATUS": dream_types.run_status_t,
             "DREAM_OBSTACLES": dream_types.obstacles_t}
    radio = 0
    for line, event in zip(lines, events):
        check(line["channel"] == event.channel and line["utime"] == event.utime,
              f"log echo: {line['channel']}@{line['utime']}, the log {event.channel}@{event.utime}")
        message = line["message"]
        if event.channel == "DREAM_POSES":
            poses = types["DREAM_POSES"].decode(event.data)
            check(line["type"] == "robot_poses_t" and message["x"] == list(poses.x) and
                  message["theta"] == list(poses.theta) and message["step"] == poses.step,
                  f"DREAM_POSES at {event.utime}: echo {message} differs from the log")
        elif event.channel.startswith("DREAM_CMD_"):
            command = dream_types.velocity_command_t.decode(event.data)
            check(line["type"] == "velocity_command_t" and message["v"] == command.v and message["w"] == command.w
                  and message["done"] == command.done, f"{event.channel}: echo {message} differs")
        elif event.channel.startswith("DREAM_RADIO_"):
            radio_message = dream_types.radio_message_t.decode(event.data)
            check(message["payload"] == bytes(radio_message.payload).hex() and
                  message["sender_id"] == radio_message.sender_id, f"{event.channel}: echo payload differs")
            radio += 1
    check(radio > 0, "the run has no radio message to check")

    code, text = ctx.run([args.dream, "log", "echo", log, "DREAM_CMD_.*", "--limit", "3"], expect=0)
    printed = [json.loads(line) for line in text.splitlines() if line.startswith("{")]
    check(len(printed) == 3 and all(p["channel"].startswith("DREAM_CMD_") for p in printed),
          f"--limit 3 on DREAM_CMD_.*: {text.strip()[:300]}")

    # A damaged DREAM_POSES (cut after 20 bytes) and another program's channel between good events.
    with open(log, "rb") as f:
        good = f.read()
    first_size = 28 + len(events[0].channel) + len(events[0].data)
    poses_data = next(e.data for e in events if e.channel == "DREAM_POSES")
    damaged_offset = first_size
    damaged = (good[:first_size] + lcm_event(1, 1, "DREAM_POSES", poses_data[:20]) +
               lcm_event(2, 2, "OTHER_APP", b"\x01\x02\x03\x04\x05\x06\x07\x08\x09") + good[first_size:])
    bad_log = ctx.path("damaged.lcmlog")
    with open(bad_log, "wb") as f:
        f.write(damaged)
    code, text = ctx.run([args.dream, "log", "echo", bad_log, ".*"])
    check(code == 0, f"log echo of a damaged message exited {code}: {text.strip()[-300:]}")
    printed = [line for line in text.splitlines() if line.startswith("{")]
    check(len(printed) == len(events), f"damaged log: {len(printed)} messages printed, expected {len(events)}")
    check(f"byte {damaged_offset} " in text and "robot_poses_t" in text,
          f"the damaged event is not reported at byte {damaged_offset}: {text.strip()[-400:]}")
    check("skipped 1 events on channels of no DREAM type: OTHER_APP (1)" in text,
          f"the foreign channel is not counted: {text.strip()[-300:]}")
    return f"log echo: {len(lines)} messages equal to the log ({radio} radio), damaged event at byte {damaged_offset}"


def test(ctx):
    args = arguments(types_dir=True)
    dream_types = import_types(args.types_dir)
    for part in (lambda: version(ctx, args), lambda: seed_and_set(ctx, args, dream_types),
                 lambda: reruns(ctx, args), lambda: sweep_default(ctx, args),
                 lambda: log_echo(ctx, args, dream_types)):
        print(part())


if __name__ == "__main__":
    main(test)
