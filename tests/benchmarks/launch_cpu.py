#!/usr/bin/python3
"""CPU per step of `dream launch` (one process per robot over udpm), two builds interleaved.

    tests/benchmarks/launch_cpu.py --build build --baseline OLD_BUILD config/hrvo_circle.yaml --pairs 5

Steps per second in wall time mean something only on a quiet machine; on a
shared one they follow the other users' load. CPU time does not: this runs
`dream launch CONFIG --steps N --all-steps` inside a private network
namespace (udpm on a ttl=0 group, needs root) and counts the user and system
time of every process of the run (the simulator and each agent: all are
waited-for children, so getrusage(RUSAGE_CHILDREN) holds them), for the
build and, if given, a baseline build, alternately, `--pairs` times each.
Each run is made twice, --steps N and --short-steps n, so that the loop's
CPU per step, (CPU(N) - CPU(n)) / (N - n), leaves out start-up (the start-up
drive, loading the config). Prints medians and each build's largest agent
peak resident memory (VmHWM, as the agents report it). Nothing here is a
pass/fail test; numbers go to docs/performance.md.
"""
import argparse
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

NETNS = ("ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
         "LCM_DEFAULT_URL='udpm://239.255.76.67:7667?ttl=0' exec \"$@\"")


def children_cpu():
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime, usage.ru_stime


def launch(build, config, steps, out):
    """One run: (user s, sys s, wall s, steps/s from summary.json, largest agent peak MB)."""
    argv = ["unshare", "-n", "sh", "-c", NETNS, "sh", os.path.join(build, "dream"), "launch", config,
            "--steps", str(steps), "--all-steps", "--out", out]
    user0, sys0 = children_cpu()
    start = time.monotonic()
    result = subprocess.run(argv, capture_output=True, text=True, check=False)
    wall = time.monotonic() - start
    user1, sys1 = children_cpu()
    if result.returncode not in (0, 3):
        sys.exit(f"{' '.join(argv)} failed ({result.returncode}): {result.stderr.strip()[-300:]}")
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    if summary.get("steps") not in (None, steps):
        sys.exit(f"{out}: ran {summary.get('steps')} steps, not {steps}")
    peaks = [float(mb) for mb in re.findall(r"peak resident memory ([0-9.]+) MB", result.stdout + result.stderr)]
    return user1 - user0, sys1 - sys0, wall, summary["steps_per_second"], max(peaks, default=0.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config")
    parser.add_argument("--build", default="build")
    parser.add_argument("--baseline", help="another build folder, run alternately with --build")
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--short-steps", type=int, default=300)
    parser.add_argument("--pairs", type=int, default=5, help="runs of each build (each a long and a short one)")
    args = parser.parse_args()
    if args.short_steps >= args.steps:
        sys.exit("--short-steps must be fewer than --steps")
    builds = [("build", args.build)] + ([("baseline", args.baseline)] if args.baseline else [])
    rows = {name: [] for name, _ in builds}
    with tempfile.TemporaryDirectory() as tmp:
        for i in range(args.pairs):
            order = builds if i % 2 == 0 else list(reversed(builds))  # neither always runs first
            for name, folder in order:
                long_run = launch(folder, args.config, args.steps, os.path.join(tmp, f"{name}{i}"))
                short_run = launch(folder, args.config, args.short_steps, os.path.join(tmp, f"{name}{i}s"))
                loop_ms = 1000 * (sum(long_run[:2]) - sum(short_run[:2])) / (args.steps - args.short_steps)
                rows[name].append((long_run, loop_ms))
                print(f"  {name:8s} run {i}: {long_run[0] + long_run[1]:6.2f} s CPU (user {long_run[0]:.2f}, "
                      f"sys {long_run[1]:.2f}), loop {loop_ms:.3f} ms CPU/step, {long_run[3]:7.0f} steps/s, "
                      f"agent peak {long_run[4]:.1f} MB", flush=True)
    print(f"{args.config}, dream launch over udpm, {args.steps} steps, medians of {args.pairs}:")
    for name, folder in builds:
        runs = rows[name]
        cpu = statistics.median(sum(r[:2]) for r, _ in runs)
        user = statistics.median(r[0] for r, _ in runs)
        system = statistics.median(r[1] for r, _ in runs)
        loop = statistics.median(ms for _, ms in runs)
        speed = statistics.median(r[3] for r, _ in runs)
        peak = max(r[4] for r, _ in runs)
        print(f"  {name} ({folder}): {1000 * cpu / args.steps:.3f} ms CPU/step whole run (user "
              f"{1000 * user / args.steps:.3f}, sys {1000 * system / args.steps:.3f}); loop {loop:.3f} ms CPU/step; "
              f"{speed:.0f} steps/s (wall, load-dependent); largest agent peak {peak:.1f} MB")


if __name__ == "__main__":
    main()
