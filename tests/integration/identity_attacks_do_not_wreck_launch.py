#!/usr/bin/python3
"""identity_attacks_do_not_wreck_launch: a `dream launch` run keeps its identity under the attacks
of issue 10 that used to freeze, end or silently steer it, ends with the poses of an undisturbed
`dream run`, and says in summary.json what it refused.

In a private network namespace, `dream launch config/go_to_goal.yaml` (simulator plus 8 agent
processes over udpm, lockstep, every step run). This script watches the bus and throws:
  - at step 10 or just after: a DREAM_POSES of the run with step 2^40 (it froze every controller),
    a DREAM_POSES of another run id, a FINISHED DREAM_STATUS of another run (it made every agent
    exit), and a radio message of the run from step 10^6 (two such jammed a sender for good);
  - from step 20: for five of robot 2's commands, a copy with its agent_id but another speed for
    the same step (it was accepted and not counted, and the log could not say which was applied);
  - a second `dream sim` on the same URL while the run goes on (agents answered both worlds).
The launch must finish every step with nobody lost, its DREAM_POSES equal to `dream run`'s, and
its summary must name the second world (other_worlds), count the conflicts and not be "clean";
the second world must name the first in its own summary and end for want of agents. The agents
must log the other run and the ignored step.

Usage: netns.sh identity_attacks_do_not_wreck_launch.py --dream BIN --source DIR --types-dir DIR
"""

import os
import time

from dreamtest import Udpm, arguments, check, import_types, main, read_summary, require_private_netns

STEPS = 3000
FORGE_AT_STEP = 10
CONFLICT_FROM_STEP = 20
CONFLICTS_SENT = 5
OTHER_RUN_ID = 0x0BADC0FFEE
FAR_STEP = 1 << 40


def forgeries(dream, run_id, step):
    """(channel, bytes) of the identity forgeries, in the run `run_id` at `step`."""
    far = dream.robot_poses_t()
    far.utime, far.step, far.run_id, far.num_robots = 0, FAR_STEP, run_id, 8
    far.x, far.y, far.theta, far.v, far.w = [0.0] * 8, [0.0] * 8, [0.0] * 8, [0.0] * 8, [0.0] * 8
    other = dream.robot_poses_t.decode(far.encode())
    other.step, other.run_id = step + 1, OTHER_RUN_ID
    finished = dream.run_status_t()
    finished.step, finished.run_id, finished.state, finished.num_robots = step, OTHER_RUN_ID, 2, 8
    finished.detail = "forged: every robot reported done"
    radio = dream.radio_message_t()
    radio.step, radio.run_id, radio.sender_id, radio.agent_id = 10 ** 6, run_id, 3, 0x5757
    radio.payload, radio.payload_size = b"\x01\x02\x03\x04", 4
    return [("DREAM_POSES", far.encode()), ("DREAM_POSES", other.encode()),
            ("DREAM_STATUS", finished.encode()), ("DREAM_RADIO_3", radio.encode())]


def attack(ctx, bus, dream, launch, args, config):
    """Throws every attack while the launch runs; returns (forged, conflicts sent, second world started)."""
    forged, conflicts, second = False, 0, False
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and launch.poll() is None:
        received = bus.receive(0.2)
        if received is None:
            continue
        channel, payload = received
        if channel == "DREAM_POSES" and not forged:
            try:
                poses = dream.robot_poses_t.decode(payload)
            except Exception:
                continue
            if poses.step >= FORGE_AT_STEP and poses.step < FAR_STEP and poses.run_id != OTHER_RUN_ID:
                for forged_channel, forged_payload in forgeries(dream, poses.run_id, poses.step):
                    bus.publish(forged_channel, forged_payload)
                forged = True
                # The second world: same URL (the namespace's default), its own folder.
                ctx.start("second", [args.dream, "sim", config, "--out", ctx.path("second"),
                                     "--set", "world.start_timeout_s=2"])
                second = True
        elif channel == "DREAM_CMD_2" and conflicts < CONFLICTS_SENT:
            try:
                command = dream.velocity_command_t.decode(payload)
            except Exception:
                continue
            if command.step >= CONFLICT_FROM_STEP and command.v != 0.15:
                command.v = 0.15  # within the limits: a plausible command, not an absurd one
                bus.publish("DREAM_CMD_2", command.encode())
                conflicts += 1
    return forged, conflicts, second


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
        forged, conflicts, second = attack(ctx, bus, dream, launch, args, config)
    finally:
        bus.close()
    launch_code = ctx.wait("launch", timeout=150)
    output = ctx.output("launch")
    check(forged and second and conflicts == CONFLICTS_SENT,
          f"the run ended before every attack was thrown (forged {forged}, second world {second}, "
          f"conflicts sent {conflicts})")
    check("did not exit cleanly" not in output, "an agent process failed under the attacks")
    summary = read_summary(launched)
    check(summary["end"] == "finished" and summary["steps"] == STEPS,
          f"summary end {summary['end']!r} after {summary['steps']} steps ({summary['reason']})")
    check(summary["robots_ever_lost"] == [], f"robots lost: {summary['robots_ever_lost']}")
    check(summary["command_conflicts"] >= 1, f"no command conflict counted: {summary['command_conflicts']}")
    check(summary["verdict"] != "clean", "a run with conflicts and a second world is reported clean")
    check(launch_code != 0, "dream launch exited 0 (ready for the Robotarium) after conflicts and a second world")
    check(summary.get("bad_message_senders", {}).get("DREAM_CMD_2") is not None,
          f"bad_message_senders does not name robot 2's conflicting sender: {summary.get('bad_message_senders')}")

    second_code = ctx.wait("second", timeout=30)
    check(second_code == 4, f"the second dream sim exited {second_code}, expected 4 (no agents of its own)")
    second_summary = read_summary(ctx.path("second"))
    check(second_summary["run_id"] in summary["other_worlds"],
          f"the launch's other_worlds {summary['other_worlds']} lacks the second world {second_summary['run_id']}")
    check(summary["run_id"] in second_summary["other_worlds"],
          f"the second world's other_worlds {second_summary['other_worlds']} lacks the launch {summary['run_id']}")
    check("another world" in output, "no process of the launch logged the second world")
    check("ignored step 1099511627776" in output, "no agent logged the forged far step")

    ctx.run([args.dream, "-q", "run", config, "--out", single] + limit, timeout=120)
    log_a, log_b = os.path.join(launched, "run.lcmlog"), os.path.join(single, "run.lcmlog")
    code, text = ctx.run([args.dream, "log", "diff", log_a, log_b, "--channels", "DREAM_POSES"])
    check(code == 0 and "same" in text, f"DREAM_POSES of the attacked launch differ from dream run: {text.strip()}")
    print(f"{STEPS} steps under attack equal to dream run; conflicts {summary['command_conflicts']}, "
          f"other worlds {summary['other_worlds']}, verdict {summary['verdict']}, exit {launch_code}")


if __name__ == "__main__":
    main(test)
