#!/usr/bin/python3
"""multiprocess_udpm_run: the same lockstep run in one process (memq) and in nine processes (udpm)
gives identical logs.

`dream launch` (the simulator plus one agent process per robot, over udpm in a private network
namespace) must finish; its DREAM_POSES, DREAM_OBSTACLES and DREAM_STATUS must equal, message by
message, those of `dream run` (one process, memq). DREAM_CMD_<n> cannot be byte-equal: each agent
process draws its own random agent_id, and on udpm an agent may answer a resent step 0 twice. So
commands are compared decoded, with agent_id ignored and repeats of the same step dropped; and the
launched run must show one distinct agent_id per robot, the one-process run a single one.

With --extra "--seed 5 --set KEY=VALUE", both runs get those overrides: dream launch must pass them
on to the simulator and every agent process (else poses or commands differ), and the launched run's
config.yaml must record them. The launch's run.lcmlog must end on one DREAM_VERDICT, summary.json's.

Usage: netns.sh multiprocess_udpm_run.py --dream BIN --source DIR --types-dir DIR [--config FILE] [--steps N]
       [--extra=WORDS]
(--config defaults to config/go_to_goal.yaml; --steps caps both runs, with --all-steps.)
"""

import os
import shlex

from dreamtest import (argument_parser, check, check_log_ends_on_verdict, import_types, main, read_events, read_summary,
                       require_private_netns)


def commands_by_robot(log_path, dream):
    """robot id -> [(step, v, w, done)] with consecutive repeats of a step dropped; and agent ids."""
    commands, agent_ids = {}, {}
    for event in read_events(log_path):
        if not event.channel.startswith("DREAM_CMD_"):
            continue
        command = dream.velocity_command_t.decode(event.data)
        robot = int(event.channel[len("DREAM_CMD_"):])
        check(command.robot_id == robot, f"{log_path}: {event.channel} carries robot_id {command.robot_id}")
        agent_ids.setdefault(robot, set()).add(command.agent_id)
        entry = (command.step, command.v, command.w, command.done)
        sequence = commands.setdefault(robot, [])
        if sequence and sequence[-1][0] == command.step:
            check(sequence[-1] == entry, f"{log_path}: robot {robot} sent two different commands for step "
                                         f"{command.step}: {sequence[-1]} and {entry}")
            continue
        sequence.append(entry)
    return commands, agent_ids


def test(ctx):
    parser = argument_parser(types_dir=True)
    parser.add_argument("--config", default="config/go_to_goal.yaml", help="relative to --source")
    parser.add_argument("--steps", type=int, default=0)
    parser.add_argument("--extra", default="", help="options for both runs, e.g. '--seed 5 --set KEY=VALUE'")
    args = parser.parse_args()
    require_private_netns()
    dream = import_types(args.types_dir)
    config = os.path.join(args.source, args.config)
    limit = ["--steps", str(args.steps), "--all-steps"] if args.steps else []
    limit += shlex.split(args.extra)

    launched, single = ctx.path("launch"), ctx.path("run")
    ctx.start("launch", [args.dream, "launch", config, "--out", launched] + limit)
    code = ctx.wait("launch", timeout=150)
    check(code == 0, f"dream launch exited {code}, expected 0")
    summary = read_summary(launched)
    check(summary["end"] == "finished", f"dream launch: summary end is {summary['end']!r} ({summary['reason']})")
    check(summary["robots_ever_lost"] == [], f"dream launch lost robots {summary['robots_ever_lost']}")
    check(summary["rejected_commands"] == 0, f"dream launch rejected {summary['rejected_commands']} commands")
    check_log_ends_on_verdict(dream, launched, code)

    if args.extra:
        # The overrides, as the folder records them (OverriddenConfig::Text).
        with open(os.path.join(launched, "config.yaml")) as f:
            header = f.readline()
        check(args.extra in header, f"dream launch: config.yaml does not name {args.extra!r}: {header.strip()}")

    ctx.run([args.dream, "-q", "run", config, "--out", single] + limit, timeout=90, expect=0)
    robots = summary["robots"]
    check(read_summary(single)["steps"] == summary["steps"],
          f"steps differ: launch {summary['steps']}, run {read_summary(single)['steps']}")
    # One writer of summaries: the launched run's carries every field of the one-process run's,
    # the same goal and verdict, and the agents' reports.
    run_summary = read_summary(single)
    missing = sorted(set(run_summary) - set(summary))
    check(not missing, f"dream launch's summary.json lacks what dream run's has: {missing}")
    check(summary["goal"] == run_summary["goal"], f"goal differs: launch {summary['goal']}, run {run_summary['goal']}")
    check(summary["verdict"] == run_summary["verdict"],
          f"verdict differs: launch {summary['verdict']}, run {run_summary['verdict']}")
    check(summary["agents"]["bad_messages"] == {}, f"dream launch: agents refused {summary['agents']['bad_messages']}")

    log_a, log_b = os.path.join(launched, "run.lcmlog"), os.path.join(single, "run.lcmlog")
    for channel in ["DREAM_POSES", "DREAM_OBSTACLES", "DREAM_STATUS"]:
        code, text = ctx.run([args.dream, "log", "diff", log_a, log_b, "--channels", channel])
        check(code == 0 and "same" in text,
              f"{channel} differs between dream launch (udpm) and dream run (memq): {text.strip()}")

    commands_a, agents_a = commands_by_robot(log_a, dream)
    commands_b, agents_b = commands_by_robot(log_b, dream)
    check(sorted(commands_a) == list(range(robots)), f"launch log has commands for robots {sorted(commands_a)}")
    for robot in range(robots):
        a, b = commands_a[robot], commands_b.get(robot, [])
        if a != b:
            first = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
            check(False, f"DREAM_CMD_{robot} differs (agent_id and repeats ignored) at command {first}: "
                         f"launch {a[first] if first < len(a) else 'none'}, run {b[first] if first < len(b) else 'none'}")
    ids_a = [next(iter(agents_a[robot])) for robot in range(robots) if len(agents_a[robot]) == 1]
    check(len(ids_a) == robots and len(set(ids_a)) == robots,
          f"dream launch: expected one distinct agent_id per robot, got {agents_a}")
    check(len(set().union(*agents_b.values())) == 1, "dream run: expected one agent_id for all robots")
    print(f"{args.config}: launch and run agree: {summary['steps']} steps, poses/obstacles/status byte-equal, "
          f"commands equal up to agent_id")


if __name__ == "__main__":
    main(test)
