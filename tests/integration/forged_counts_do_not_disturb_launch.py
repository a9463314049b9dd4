#!/usr/bin/python3
"""forged_counts_do_not_disturb_launch: messages whose counts lie about their size are refused by
every process of a `dream launch` run, which then ends exactly as an undisturbed `dream run`.

In a private network namespace, `dream launch config/go_to_goal.yaml` (simulator plus 8 agent
processes over udpm, lockstep). This script watches DREAM_POSES and, at two steps, sends each of
these once (correct fingerprints, so only the counts are wrong):
  - the issue's 48-byte DREAM_POSES with num_robots = 2^28 (it crashed every C++ agent)
  - the issue's 79-byte DREAM_STATUS with num_lost = 2^28 (it made agents allocate 1 GB)
  - DREAM_OBSTACLES with num_obstacles = -1 and with a count whose byte size wraps 32 bits
  - DREAM_RADIO_3 with payload_size = 2^28
  - well-formed radio messages from 600 senders that are not robots of the run (memory)
  - DREAM_FAULT_1 with a detail string length of 2^28 (the simulator's input)
  - a truncated DREAM_CMD_1 that still carries its agent_id (50 of its 61 bytes)
The launch must exit 0 with no agent failing, nobody lost, no command rejected; its DREAM_POSES
must equal `dream run`'s message by message; summary.json must count DREAM_FAULT_1 and DREAM_CMD_1
in bad_messages and name the forger's agent_id in bad_message_senders; the agents must log each
refused channel; run.lcmlog must end on one DREAM_VERDICT, summary.json's with the agents' reason.

Usage: netns.sh forged_counts_do_not_disturb_launch.py --dream BIN --source DIR --types-dir DIR
"""

import os
import struct
import time

from dreamtest import (Udpm, arguments, check, check_log_ends_on_verdict, import_types, main, read_summary,
                       require_private_netns)

STEPS = 600  # long enough that the second round reaches the world before its end on a busy machine
INJECT_AT_STEPS = (5, 40)
FORGER_AGENT_ID = 0x0BADC0DE0BADC0DE
FOREIGN_SENDERS = range(1000, 1600)


def forged_messages(dream, run_id):
    """(channel, bytes) of every forgery, in the run `run_id` (copied from the bus, as a forger would)."""
    def fingerprint(kind):
        return kind._get_packed_fingerprint()

    # The 48-byte DREAM_POSES with num_robots 2^28 (the run id now inside it).
    poses = fingerprint(dream.robot_poses_t) + struct.pack(">qqqi", 0, 5, run_id, 1 << 28) + bytes(12)
    status = (fingerprint(dream.run_status_t) + struct.pack(">qqqbi", 0, 5, run_id, 1, 8) + bytes(48) +
              struct.pack(">i", 1 << 28) + bytes(6))
    check(len(poses) == 48 and len(status) == 95, "internal: the forged datagram sizes")
    obstacles_negative = fingerprint(dream.obstacles_t) + struct.pack(">qqqi", 0, 5, run_id, -1)
    # 52 bytes per obstacle: 52 * 0x4EC4EC5 = 2^32 + 4, so a 32-bit size would say "4 bytes".
    obstacles_wrapping = fingerprint(dream.obstacles_t) + struct.pack(">qqqi", 0, 5, run_id, 0x4EC4EC5) + bytes(4)
    radio = (fingerprint(dream.radio_message_t) + struct.pack(">qqqiqi", 0, 5, run_id, 3, FORGER_AGENT_ID, 1 << 28) +
             bytes(16))
    fault = (fingerprint(dream.robot_fault_t) + struct.pack(">qqqiqi", 0, 5, run_id, 1, FORGER_AGENT_ID, 1 << 28) +
             b"x" * 8)
    command = dream.velocity_command_t()
    command.step, command.run_id, command.robot_id, command.agent_id, command.v = 5, run_id, 1, FORGER_AGENT_ID, 0.1
    messages = [("DREAM_POSES", poses), ("DREAM_STATUS", status), ("DREAM_OBSTACLES", obstacles_negative),
                ("DREAM_OBSTACLES", obstacles_wrapping), ("DREAM_RADIO_3", radio), ("DREAM_FAULT_1", fault),
                ("DREAM_CMD_1", command.encode()[:50])]
    for sender in FOREIGN_SENDERS:
        foreign = dream.radio_message_t()
        foreign.step, foreign.run_id, foreign.sender_id, foreign.agent_id = 5, run_id, sender, FORGER_AGENT_ID
        foreign.payload, foreign.payload_size = b"12345678", 8
        messages.append((f"DREAM_RADIO_{sender}", foreign.encode()))
    return messages


def inject_while_running(bus, dream, launch):
    """Sends the forgeries at INJECT_AT_STEPS (or at the first step seen after one, as this
    socket may miss a DREAM_POSES when the machine is busy); returns how many rounds were sent."""
    rounds = set()
    deadline = time.monotonic() + 90
    while time.monotonic() < deadline and launch.poll() is None and len(rounds) < len(INJECT_AT_STEPS):
        received = bus.receive(0.2)
        if received is None or received[0] != "DREAM_POSES":
            continue
        try:
            poses = dream.robot_poses_t.decode(received[1])
            step, run_id = poses.step, poses.run_id
        except Exception:
            continue  # our own forgery coming back
        due = [target for target in INJECT_AT_STEPS if target not in rounds and target <= step]
        if due:
            for channel, payload in forged_messages(dream, run_id):
                bus.publish(channel, payload)
            rounds.update(due[:1])
    return len(rounds)


def test(ctx):
    args = arguments(types_dir=True)
    require_private_netns()
    dream = import_types(args.types_dir)
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    limit = ["--steps", str(STEPS), "--all-steps"]
    launched, single = ctx.path("launch"), ctx.path("run")

    bus = Udpm(receive=True)
    try:
        launch = ctx.start("launch", [args.dream, "launch", config, "--out", launched] + limit)
        rounds = inject_while_running(bus, dream, launch)
    finally:
        bus.close()
    code = ctx.wait("launch", timeout=120)
    output = ctx.output("launch")
    # 5: the run finished with the right poses, and its verdict names the bad messages (not ready).
    check(code == 5, f"dream launch exited {code} under forged messages, expected 5: {output[-800:]}")
    check("bad_messages: " in output, f"the printed verdict does not name the bad messages: {output[-800:]}")
    check(rounds == len(INJECT_AT_STEPS), f"the run ended before every forgery round was sent ({rounds})")
    check("did not exit cleanly" not in output, "an agent process failed under forged messages")
    summary = read_summary(launched)
    check(summary["end"] == "finished" and summary["steps"] == STEPS,
          f"summary end {summary['end']!r} after {summary['steps']} steps ({summary['reason']})")
    check(summary["robots_ever_lost"] == [], f"robots lost: {summary['robots_ever_lost']}")
    check(summary["rejected_commands"] == 0, f"rejected_commands is {summary['rejected_commands']}, expected 0")

    bad = summary["bad_messages"]
    for channel in ["DREAM_FAULT_1", "DREAM_CMD_1"]:
        check(bad.get(channel) == len(INJECT_AT_STEPS), f"bad_messages {bad} does not count {channel} twice")
        senders = summary["bad_message_senders"].get(channel, [])
        check(FORGER_AGENT_ID in senders, f"bad_message_senders does not name the forger on {channel}: {senders}")
    # The agents' own inputs: each agent logs the first refusal per channel.
    for channel in ["DREAM_POSES", "DREAM_STATUS", "DREAM_OBSTACLES", "DREAM_RADIO_3", "DREAM_RADIO_1000"]:
        check(f"{channel}: dropped bad message #1" in output, f"no agent logged the forged message on {channel}")
    check("is not a robot of this run" in output, "no agent refused the radio senders outside the run")
    # ... and dream launch merges what the agents refused into summary.json.
    agents_bad = summary.get("agents", {}).get("bad_messages", {})
    for channel in ["DREAM_POSES", "DREAM_STATUS", "DREAM_OBSTACLES", "DREAM_RADIO_3", "DREAM_RADIO_1000"]:
        check(agents_bad.get(channel, 0) >= 8, f"summary.json agents.bad_messages does not count {channel} "
                                               f"for every agent: {agents_bad.get(channel)}")
    agent_reasons = [r for r in summary["verdict_reasons"] if r["rule"] == "agent_bad_messages"]
    check(agent_reasons, f"the agents' refusals are not a verdict reason: {summary['verdict_reasons']}")
    # The reason says on which channels, how many, and what was refused first (not only a count).
    problem = agent_reasons[0]["problem"] if agent_reasons else ""
    check(any(f"{channel}: " in problem for channel in agents_bad) and "first refused: " in problem
          and "(the agent of robot " in problem, f"the agents' reason does not say what was refused: {problem}")
    # The last verdict printed is the one summary.json holds, the agents' reports included.
    verdicts = [line for line in output.splitlines() if line.startswith("verdict: ")]
    check(verdicts and verdicts[-1].startswith(f"verdict: {summary['verdict']} (with the agents' reports"),
          f"the launch's last printed verdict is not summary.json's {summary['verdict']!r}: {verdicts}")
    # ... and the log's one DREAM_VERDICT, its last event, is summary.json's, the agents' reason included.
    logged = check_log_ends_on_verdict(dream, launched, code)
    check("agent_bad_messages: " in logged.reasons, f"the log's verdict lacks the agents' reason: {logged.reasons}")

    ctx.run([args.dream, "-q", "run", config, "--out", single] + limit, timeout=90, expect=0)
    log_a, log_b = os.path.join(launched, "run.lcmlog"), os.path.join(single, "run.lcmlog")
    code, text = ctx.run([args.dream, "log", "diff", log_a, log_b, "--channels", "DREAM_POSES"])
    check(code == 0 and "same" in text, f"DREAM_POSES of the attacked launch differ from dream run: {text.strip()}")
    check(summary["final_poses"] == read_summary(single)["final_poses"], "final poses differ from dream run")
    print(f"{rounds} rounds of {len(forged_messages(dream, 1))} forged messages refused; poses equal to dream run; "
          f"bad_messages {bad}")


if __name__ == "__main__":
    main(test)
