#!/usr/bin/python3
"""foreign_packets_do_not_crash: garbage and hostile commands on the bus are refused and counted,
never fatal.

In a private network namespace: `dream sim` (lockstep, 150 steps, no early stop) and
`dream agent --robots 0,1,3-7`; this script itself drives robot 2 over raw udpm (it answers every
DREAM_POSES with v = 0.02 m/s), so it can send robot 2 a NaN command for exactly one step. At
step 10 it also sends, once each:
  - bytes that are no LCM type, on DREAM_CMD_3
  - a robot_poses_t (a foreign type) on DREAM_CMD_x
  - a velocity_command_t for robot 99 on DREAM_CMD_99
  - a velocity_command_t claiming robot 4 on DREAM_CMD_5
  - a command for robot 3 from a second agent id
  - a truncated velocity_command_t on DREAM_CMD_4, an empty message on DREAM_CMD_6
  - garbage on DREAM_POSES and DREAM_STATUS (the agents' inputs)
  - a datagram that is not LCM at all, and a malformed LCM fragment
  - a forged DREAM_APPLIED (a command "applied" to robot 0) and DREAM_MEASURED_POSES, the world's
    own records; at step 30, messages on 300 made-up channel names
The run must finish (exit 0 or 3), every agent process too (exit 0), nobody may be lost; the
summary must count the 4 rejected commands and name each bad channel in bad_messages, with its
first step in refused_messages; robot 2 must hold still in the step of its NaN command; the log
must stay readable and hold none of the refused messages: refused.lcmlog beside it holds them
(issue 23: the forged DREAM_APPLIED showed in `dream log echo` as applied, the run clean).

Usage: netns.sh foreign_packets_do_not_crash.py --dream BIN --source DIR --types-dir DIR
"""

import math
import os
import struct
import time

from dreamtest import (
    Udpm, arguments, check, config_with, import_types, main, read_events, read_summary, require_private_netns,
)

OUR_AGENT_ID = 0x0D1E5E1F0D1E5E1F
STRANGER_AGENT_ID = 0x5757575757575757
INJECT_AT_STEP = 10
NAN_AT_STEP = 20
STEPS = 150
MADE_UP_CHANNELS = 300  # past BadMessageLog's and RefusedRecord's 256 named channels
MADE_UP_AT_STEP = 30     # after the others, which are named before the table fills


def command(dream, step, run_id, robot_id, v, w=0.0, agent_id=OUR_AGENT_ID):
    message = dream.velocity_command_t()
    message.utime = step * 33000
    message.step = step
    message.run_id = run_id
    message.robot_id = robot_id
    message.agent_id = agent_id
    message.v = v
    message.w = w
    message.done = False
    return message.encode()


def inject(bus, dream, step, run_id):
    """Sends every foreign message once; returns {channel: what} the sim must count as bad."""
    poses = dream.robot_poses_t()
    poses.num_robots = 1
    poses.x, poses.y, poses.theta, poses.v, poses.w = [0.0], [0.0], [0.0], [0.0], [0.0]
    bus.publish("DREAM_CMD_3", b"\xde\xad\xbe\xef not an LCM message at all")
    bus.publish("DREAM_CMD_x", poses.encode())
    bus.publish("DREAM_CMD_99", command(dream, step, run_id, 99, 0.1))
    bus.publish("DREAM_CMD_5", command(dream, step, run_id, 4, 0.1))
    bus.publish("DREAM_CMD_3", command(dream, step, run_id, 3, 0.1, agent_id=STRANGER_AGENT_ID))
    bus.publish("DREAM_CMD_4", command(dream, step, run_id, 4, 0.1)[:20])
    bus.publish("DREAM_CMD_6", b"")
    applied = dream.applied_commands_t()
    applied.step, applied.run_id, applied.num_robots = step, run_id, 1
    applied.applied_agent_id, applied.commanded_v, applied.commanded_w, applied.conflicts = [666], [9.0], [0.0], [0]
    bus.publish("DREAM_APPLIED", applied.encode())
    bus.publish("DREAM_MEASURED_POSES", poses.encode())
    bus.publish("DREAM_POSES", b"\x00" * 40)
    bus.publish("DREAM_STATUS", os.urandom(64))
    bus.send_raw(b"hello, this is no LCM packet")
    # A fragment header (magic LC03) announcing an absurd message and fragment count.
    bus.send_raw(struct.pack(">IIIIHH", 0x4C433033, 7, 0x7FFFFFFF, 0x7FFFFFF0, 3, 2) + b"DREAM_CMD_1\0junk")
    # The world reads DREAM_STATUS too (a second world's would name another run), so the random
    # bytes there are a bad message of its own.
    return {"DREAM_CMD_3", "DREAM_CMD_x", "DREAM_CMD_99", "DREAM_CMD_5", "DREAM_CMD_4", "DREAM_CMD_6", "DREAM_STATUS",
            "DREAM_APPLIED", "DREAM_MEASURED_POSES"}


def drive_robot_2(ctx, bus, dream, sim):
    """Answers DREAM_POSES for robot 2 until the world finishes; injects the foreign messages."""
    bad_channels, injected, nan_sent, made_up_sent = set(), False, False, False
    deadline = time.monotonic() + 30
    while time.monotonic() < deadline:
        # 5: finished, but not ready (the bad messages are a reason of its verdict).
        check(sim.poll() is None or sim.returncode in (0, 3, 5),
              f"dream sim exited {sim.returncode} while the foreign packets were on the bus")
        if sim.poll() is not None:
            break
        received = bus.receive(0.2)
        if received is None:
            continue
        channel, payload = received
        if channel == "DREAM_STATUS":
            try:
                status = dream.run_status_t.decode(payload)
            except Exception:
                continue  # our own garbage
            if status.state in (dream.run_status_t.FINISHED, dream.run_status_t.ABORTED):
                break
        if channel != "DREAM_POSES":
            continue
        try:
            poses = dream.robot_poses_t.decode(payload)
        except Exception:
            continue  # our own garbage
        if poses.step == INJECT_AT_STEP and not injected:
            bad_channels = inject(bus, dream, poses.step, poses.run_id)
            injected = True
        if poses.step == MADE_UP_AT_STEP and not made_up_sent:
            for i in range(MADE_UP_CHANNELS):
                bus.publish(f"MADE_UP_{i}", b"x" * 1000)
            made_up_sent = True
        if poses.step == NAN_AT_STEP:
            if not nan_sent:
                bus.publish("DREAM_CMD_2", command(dream, poses.step, poses.run_id, 2, math.nan))
                nan_sent = True
            continue
        bus.publish("DREAM_CMD_2", command(dream, poses.step, poses.run_id, 2, 0.02))
    check(injected and nan_sent and made_up_sent, f"the run ended before step {MADE_UP_AT_STEP}: nothing was injected")
    return bad_channels


def test(ctx):
    args = arguments(types_dir=True)
    require_private_netns()
    dream = import_types(args.types_dir)
    config = config_with(os.path.join(args.source, "config", "go_to_goal.yaml"), ctx.path("foreign.yaml"),
                         steps=STEPS, stop_when_done=False, start_timeout_s=10)
    out = ctx.path("run")

    bus = Udpm(receive=True)
    sim = ctx.start("sim", [args.dream, "sim", config, "--out", out])
    ctx.start("agents", [args.dream, "agent", config, "--robots", "0,1,3-7"])
    try:
        bad_channels = drive_robot_2(ctx, bus, dream, sim)
    finally:
        bus.close()

    sim_code = ctx.wait("sim", timeout=20)
    check(sim_code in (0, 3, 5), f"dream sim exited {sim_code}, expected 0, 3 or 5")
    code = ctx.wait("agents", timeout=10)
    check(code == 0, f"dream agent exited {code} after the foreign packets, expected 0")
    summary = read_summary(out)
    check(summary["end"] == "finished" and summary["steps"] == STEPS,
          f"summary end {summary['end']!r} after {summary['steps']} steps ({summary['reason']})")
    check(summary["robots_ever_lost"] == [], f"robots lost: {summary['robots_ever_lost']}")
    # Refused commands: robot 99, robot_id 4 on DREAM_CMD_5, the stranger on robot 3, NaN on robot 2.
    check(summary["rejected_commands"] == 4, f"rejected_commands is {summary['rejected_commands']}, expected 4")
    check(summary["verdict"] == "not_ready" and
          "bad_messages" in [reason["rule"] for reason in summary["verdict_reasons"]],
          f"bad messages should make the verdict not_ready: {summary['verdict']} {summary['verdict_reasons']}")
    bad = summary["bad_messages"]
    missing = sorted((bad_channels | {"DREAM_CMD_2"}) - set(bad))
    check(not missing, f"bad_messages {bad} lacks {missing}")
    made_up = {channel for channel in bad if channel.startswith("MADE_UP_")}
    check(len(made_up) + len(bad_channels) + 1 == 256 and bad.get("(other channels)", 0) > 0,
          f"bad_messages names {len(bad)} channels, expected 256 and the rest under (other channels)")
    check(not set(bad) - bad_channels - made_up - {"DREAM_CMD_2", "(other channels)"},
          f"bad_messages names unexpected channels: {sorted(set(bad) - made_up)}")
    refused = summary["refused_messages"]
    for channel in ["DREAM_APPLIED", "DREAM_MEASURED_POSES", "DREAM_CMD_99"]:
        check(refused.get(channel, {}).get("first_step") == INJECT_AT_STEP,
              f"refused_messages {channel}: {refused.get(channel)}, expected first_step {INJECT_AT_STEP}")
    reason = next(r for r in summary["verdict_reasons"] if r["rule"] == "bad_messages")
    check(f"first at step {INJECT_AT_STEP}" in reason["problem"] and "refused.lcmlog" in reason["find_out"],
          f"the verdict's reason does not give the first step and the refused log: {reason}")
    # Counted and logged: the first bad message of each channel gets a warning line.
    sim_output = ctx.output("sim")
    for channel in sorted(bad_channels):
        check(f"{channel}: dropped bad message #1:" in sim_output,
              f"dream sim logged nothing for the bad message on {channel}")

    log = os.path.join(out, "run.lcmlog")
    code, text = ctx.run([args.dream, "log", "info", log])
    check(code == 0, f"dream log info refuses the log: {text.strip()}")
    for channel in ["DREAM_CMD_x", "DREAM_CMD_99", "DREAM_APPLIED", "MADE_UP_"]:
        check(channel not in text or channel == "DREAM_APPLIED", f"the log holds refused messages on {channel}")
    applied_agents = {agent for event in read_events(log) if event.channel == "DREAM_APPLIED"
                      for agent in dream.applied_commands_t.decode(event.data).applied_agent_id}
    check(666 not in applied_agents, "the forged DREAM_APPLIED is in the run's log")
    refused_log = os.path.join(out, summary["refused_log"])
    refused_channels = {event.channel for event in read_events(refused_log)}
    check({"DREAM_APPLIED", "DREAM_MEASURED_POSES", "DREAM_CMD_x", "DREAM_CMD_99", "MADE_UP_0"} <= refused_channels,
          f"{refused_log} lacks refused messages: it holds {sorted(refused_channels)[:12]}")
    code, text = ctx.run([args.dream, "log", "echo", refused_log, "DREAM_APPLIED"])
    check(code == 0 and '"applied_agent_id":[666]' in text.replace(" ", ""),
          f"dream log echo does not show the refused DREAM_APPLIED: {text.strip()[:500]}")
    robot_2 = {}
    for event in read_events(log):
        if event.channel == "DREAM_POSES":
            poses = dream.robot_poses_t.decode(event.data)
            robot_2[poses.step] = (poses.x[2], poses.y[2], poses.theta[2])
    check(robot_2[NAN_AT_STEP + 1] == robot_2[NAN_AT_STEP],
          f"robot 2 moved in the step of its NaN command: {robot_2[NAN_AT_STEP]} -> {robot_2[NAN_AT_STEP + 1]}")
    check(robot_2[NAN_AT_STEP] != robot_2[NAN_AT_STEP - 1],
          "robot 2 did not move under its (Python) agent's commands before the NaN step")
    print(f"{summary['rejected_commands']} commands rejected, bad messages {bad}, sim exit {sim_code}")


if __name__ == "__main__":
    main(test)
