#!/usr/bin/python3
"""lossy_three_namespaces: a lockstep run split over three network namespaces joined by a lossy,
delaying, reordering link gives the pose log of `dream run` (issue 10 item 7).

Run under netns.sh: its private namespace is the middle one. The test makes three more, world,
agents_a and agents_b (each held by an `unshare -n sleep` process), and joins each to the middle by
a veth pair. The pieces `dream launch` starts, started by hand as the README shows for several
machines: `dream sim` in world, one `dream agent --robots N` process per robot, robots 0-3 in
agents_a and 4-7 in agents_b, all on udpm with ttl=1. Between the namespaces every datagram is
impaired as `tc qdisc ... netem loss 5% delay 20ms reorder 25% 50%` does:

- with netem in the kernel: a bridge in the middle namespace, netem on each of its ports;
- without it (no sch_netem, as on the CI machine): lossy_relay.py in the middle namespace, the only
  path between them, drops 5% per outgoing link, holds the rest 20 ms and sends 25% at once.

The test prints which impairment it used, checks that it dropped and (relay) reordered datagrams,
that the run finished with no robot lost, and that DREAM_POSES, DREAM_OBSTACLES and DREAM_STATUS
equal those of `dream run` (one process, memq) message by message. Namespaces that cannot reach
each other fail it (the world waits for agents it never hears); it skips (77) only when veth pairs
or namespaces cannot be made.

Usage: netns.sh lossy_three_namespaces.py --dream BIN --source DIR --types-dir DIR [--config FILE] [--steps N]
       [--impairment auto|netem|relay|bridge]   (bridge: the kernel path without netem, to check plumbing)
"""

import json
import os
import re
import subprocess
import sys

from dreamtest import (argument_parser, check, fail, import_types, main, read_events, read_summary,
                       require_private_netns)

HERE = os.path.dirname(os.path.abspath(__file__))
GROUP, PORT = "239.255.76.67", 7667
URL = f"udpm://{GROUP}:{PORT}?ttl=1"
NETEM = ["netem", "loss", "5%", "delay", "20ms", "reorder", "25%", "50%"]
# Faster resends keep a step lost to the link short; start_timeout_s fails a run whose namespaces
# cannot talk in 15 s instead of 30. Neither changes what the world computes.
SETS = ["--set", "world.resend_interval_s=0.05", "--set", "world.start_timeout_s=15"]
NAMESPACES = {"world": "10.77.1", "agents_a": "10.77.2", "agents_b": "10.77.3"}


def sh(argv, what):
    """Runs a setup command; fails the test with its output when it fails."""
    result = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=20)
    if result.returncode != 0:
        fail(f"{what}: `{' '.join(argv)}` exited {result.returncode}: {result.stdout.strip()}")
    return result.stdout


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(77)


def netem_available():
    """True when the kernel takes a netem qdisc (tried on a veth pair made and removed here)."""
    probe = subprocess.run(["ip", "link", "add", "name", "probe0", "type", "veth", "peer", "name", "probe1"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if probe.returncode != 0:
        skip(f"cannot make a veth pair: {probe.stdout.strip()}")
    try:
        result = subprocess.run(["tc", "qdisc", "add", "dev", "probe0", "root"] + NETEM,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if result.returncode != 0:
            print(f"tc netem is not available here ({result.stdout.strip()}); impairing in user space")
        return result.returncode == 0
    finally:
        subprocess.run(["ip", "link", "del", "probe0"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def make_namespaces(ctx, bridge):
    """Starts one namespace holder per NAMESPACES entry and joins it to this namespace by a veth pair
    (m_<name> here, e0 there), addressed 10.77.x.1 / 10.77.x.2, multicast routed out of e0. With
    bridge, the m_ ends are ports of br0; else they stay apart (the relay joins them).
    Returns name -> holder pid."""
    holders = {}
    for name, prefix in NAMESPACES.items():
        holder = ctx.start(f"ns_{name}", ["unshare", "-n", "sleep", "3600"])
        holders[name] = holder.pid
        inside = ["nsenter", "-t", str(holder.pid), "-n", "--"]
        # unshare has exec'd sleep once /proc/<pid>/ns/net differs from ours.
        for _ in range(200):
            if os.readlink(f"/proc/{holder.pid}/ns/net") != os.readlink("/proc/self/ns/net"):
                break
            check(holder.poll() is None, f"unshare -n for {name} exited {holder.returncode}: {ctx.output(f'ns_{name}')}")
            subprocess.run(["sleep", "0.01"])
        else:
            fail(f"the {name} namespace holder never left this namespace")
        outside = f"m_{name}"[:15]
        made = subprocess.run(["ip", "link", "add", "name", outside, "type", "veth", "peer", "name", "e0",
                               "netns", str(holder.pid)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if made.returncode != 0:
            skip(f"cannot make a veth pair into a namespace: {made.stdout.strip()}")
        sh(["ip", "addr", "add", f"{prefix}.1/24", "dev", outside], "address the middle end")
        sh(["ip", "link", "set", outside, "up"], "bring up the middle end")
        sh(inside + ["ip", "link", "set", "lo", "up"], f"{name}: loopback up")
        sh(inside + ["ip", "addr", "add", f"{prefix}.2/24", "dev", "e0"], f"{name}: address")
        sh(inside + ["ip", "link", "set", "e0", "up"], f"{name}: link up")
        sh(inside + ["ip", "route", "add", "224.0.0.0/4", "dev", "e0"], f"{name}: multicast route")
        if bridge:
            sh(["ip", "link", "set", outside, "master", "br0"], "bridge port")
    return holders


def in_namespace(holders, name, argv):
    return ["nsenter", "-t", str(holders[name]), "-n", "--"] + argv


def netem_drops(links):
    """Datagrams netem dropped on the bridge ports (tc -s qdisc)."""
    total = 0
    for link in links:
        text = sh(["tc", "-s", "qdisc", "show", "dev", link], "read netem counts")
        total += sum(int(n) for n in re.findall(r"dropped (\d+)", text))
    return total


def plain(value):
    """An LCM message (nested ones and lists of them too) as plain Python values, comparable with ==."""
    if hasattr(value, "__slots__"):
        return {field: plain(getattr(value, field)) for field in value.__slots__}
    if isinstance(value, (list, tuple)):
        return [plain(item) for item in value]
    return value


def world_messages(log_path, channel, message_type):
    """The messages on `channel` of a run log, decoded, as field dicts without run_id: each run draws
    its own run id (the run's identity, issue 10 item 2), everything else must be equal."""
    messages = []
    for event in read_events(log_path):
        if event.channel == channel:
            message = message_type.decode(event.data)
            fields = plain(message)
            fields.pop("run_id", None)
            messages.append(fields)
    return messages


def test(ctx):
    parser = argument_parser(types_dir=True)
    parser.add_argument("--config", default="config/go_to_goal.yaml", help="relative to --source")
    parser.add_argument("--steps", type=int, default=150)
    parser.add_argument("--impairment", choices=["auto", "netem", "relay", "bridge"], default="auto")
    args = parser.parse_args()
    require_private_netns()
    config = os.path.join(args.source, args.config)
    impairment = args.impairment
    if impairment == "auto":
        impairment = "netem" if netem_available() else "relay"
    links = [f"m_{name}"[:15] for name in NAMESPACES]

    if impairment in ("netem", "bridge"):
        sh(["ip", "link", "add", "name", "br0", "type", "bridge", "mcast_snooping", "0"], "make the bridge")
        sh(["ip", "link", "set", "br0", "up"], "bring up the bridge")
    holders = make_namespaces(ctx, bridge=impairment in ("netem", "bridge"))
    stats_path = ctx.path("relay.json")
    if impairment == "netem":
        for link in links:
            sh(["tc", "qdisc", "add", "dev", link, "root"] + NETEM, "netem on a bridge port")
        print(f"impairment: kernel netem on every bridge port ({' '.join(NETEM[1:])})")
    elif impairment == "relay":
        ctx.start("relay", [sys.executable, os.path.join(HERE, "lossy_relay.py"), "--links", ",".join(links),
                            "--stats", stats_path, "--loss", "0.05", "--delay", "0.020", "--reorder", "0.25"])
        ctx.wait_for_output("relay", r"relaying", timeout=10)
        print("impairment: user-space relay (tests/integration/lossy_relay.py): 5% loss per link, 20 ms delay, "
              "25% sent at once (reordered)")
    else:
        print("impairment: none (a kernel bridge, to check the plumbing)")

    # The pieces dream launch starts, in three namespaces.
    steps = ["--steps", str(args.steps), "--all-steps"]
    launched, single = ctx.path("launch"), ctx.path("run")
    ctx.start("sim", in_namespace(holders, "world", [args.dream, "sim", config, "--lcm-url", URL,
                                                     "--out", launched] + steps + SETS))
    with open(config) as f:
        robots = int(re.search(r"^robots:\s*(\d+)", f.read(), re.MULTILINE).group(1))
    agents = []
    for robot in range(robots):
        where = "agents_a" if robot < robots // 2 else "agents_b"
        name = f"agent_{robot}"
        ctx.start(name, in_namespace(holders, where, [args.dream, "agent", config, "--lcm-url", URL,
                                                      "--robots", str(robot)] + SETS))
        agents.append(name)
    code = ctx.wait("sim", timeout=150)
    check(code == 0, f"dream sim (namespace world) exited {code}, expected 0")
    for name in agents:
        code = ctx.wait(name, timeout=30)
        check(code == 0, f"{name} exited {code}, expected 0")
    summary = read_summary(launched)
    check(summary["end"] == "finished", f"summary end is {summary['end']!r} ({summary['reason']})")
    check(summary["robots_ever_lost"] == [], f"robots lost across the impaired link: {summary['robots_ever_lost']}")
    check(summary["steps"] == args.steps, f"ran {summary['steps']} steps, expected {args.steps}")

    # The impairment happened: datagrams were dropped (and, by the relay, reordered) on every link.
    if impairment == "relay":
        ctx.procs["relay"][0].terminate()
        ctx.wait("relay", timeout=10)
        with open(stats_path) as f:
            counts = json.load(f)["links"]
        for link, c in counts.items():
            check(c["received"] > 0 and c["sent"] > 0, f"relay: nothing crossed link {link}: {c}")
        dropped = sum(c["dropped"] for c in counts.values())
        reordered = sum(c["reordered"] for c in counts.values())
        sent = sum(c["sent"] for c in counts.values())
        check(dropped > 0 and reordered > 0, f"relay: dropped {dropped}, reordered {reordered}: not impaired")
        impaired = f"relay sent {sent} datagrams, dropped {dropped}, reordered {reordered}"
    elif impairment == "netem":
        dropped = netem_drops(links)
        check(dropped > 0, "netem dropped nothing")
        impaired = f"netem dropped {dropped} datagrams"
    else:
        impaired = "not impaired"

    ctx.run([args.dream, "-q", "run", config, "--out", single] + steps + SETS, timeout=90, expect=0)
    log_a, log_b = os.path.join(launched, "run.lcmlog"), os.path.join(single, "run.lcmlog")
    dream = import_types(args.types_dir)
    for channel, message_type in [("DREAM_POSES", dream.robot_poses_t), ("DREAM_OBSTACLES", dream.obstacles_t),
                                  ("DREAM_STATUS", dream.run_status_t)]:
        a, b = world_messages(log_a, channel, message_type), world_messages(log_b, channel, message_type)
        check(len(a) == len(b), f"{channel}: {len(a)} messages across the namespaces, {len(b)} in dream run")
        for index, (x, y) in enumerate(zip(a, b)):
            if x != y:
                fields = sorted(field for field in x if x[field] != y[field])
                fail(f"{channel} message {index} (step {x.get('step')}) differs from dream run's in {fields}")
        check(channel != "DREAM_POSES" or len(a) == args.steps + 1,
              f"DREAM_POSES: {len(a)} messages for {args.steps} steps")
    print(f"{args.config}: {summary['steps']} steps across world / agents_a / agents_b ({impaired}); "
          f"DREAM_POSES, DREAM_OBSTACLES, DREAM_STATUS equal dream run's")


if __name__ == "__main__":
    main(test)
