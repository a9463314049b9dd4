#!/usr/bin/python3
"""The robustness table of docs/experiments.md ("Robustness: ideal vs lab"): every shipped
experiment under world.realism ideal and lab over 20 seeds, with `dream sweep`.

    tests/benchmarks/realism_robustness.py --dream build/dream --out /tmp/robustness

runs, for each config, `dream sweep config/<name>.yaml --seeds 1-20 --set world.realism=ideal,lab`
into <out>/<name>, then prints one Markdown row per experiment and preset: success rate, the
closest approach (smallest and median over the seeds of each run's closest pair of robot
centres), runs with violations (boundary, collision or obstacle errors) and their total, runs with
actuator errors, and how many distinct trajectories the seeds gave (1: the seed changes nothing).
Standard library only.
"""

import argparse
import csv
import os
import statistics
import subprocess
import sys

EXPERIMENTS = ["go_to_goal", "hrvo_circle", "line_deployment", "voronoi_coverage", "voronoi_coverage_static",
               "affine_formation"]
PRESETS = ["ideal", "lab"]


def sweep(dream, source, name, out_dir, seeds, jobs):
    os.makedirs(os.path.dirname(out_dir) or ".", exist_ok=True)
    if os.path.exists(os.path.join(out_dir, "sweep.csv")):
        return  # already swept (rerun with another --out to start over)
    argv = [dream, "sweep", os.path.join(source, "config", name + ".yaml"), "--seeds", seeds, "--set",
            "world.realism=" + ",".join(PRESETS), "--jobs", str(jobs), "--out", out_dir, "-q"]
    print(" ".join(argv), file=sys.stderr, flush=True)
    result = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if not os.path.exists(os.path.join(out_dir, "sweep.csv")):
        sys.exit(f"{name}: dream sweep wrote no sweep.csv (exit {result.returncode}): {result.stdout[-2000:]}")


def realism_column(header):
    for column in header:
        if column.endswith("realism"):
            return column
    sys.exit(f"sweep.csv has no realism column: {header}")


def row_for(name, preset, rows):
    ran = [r for r in rows if r["status"] in ("ran", "failed")]
    successes = sum(1 for r in ran if r["success"] in ("1", "true", "True", "yes"))
    distances = [float(r["min_distance_m"]) for r in ran if r["min_distance_m"] not in ("", "nan")]
    violations = [int(r["boundary_errors"]) + int(r["collision_errors"]) + int(r["obstacle_collisions"])
                  for r in ran]
    actuator = sum(1 for r in ran if int(r["actuator_errors"]) > 0)
    # Runs with identical outcomes (steps, closest approach, completion) followed the same trajectory.
    distinct = len({(r["steps"], r["min_distance_m"], r["completion_step"]) for r in ran})
    closest = f"{min(distances):.3f} / {statistics.median(distances):.3f}" if distances else "-"
    return (f"| {name} | {preset} | {successes}/{len(ran)} | {closest} | "
            f"{sum(1 for v in violations if v > 0)} ({sum(violations)}) | {actuator} | {distinct} |")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--dream", default="build/dream")
    parser.add_argument("--source", default=".")
    parser.add_argument("--out", required=True)
    parser.add_argument("--seeds", default="1-20")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    lines = ["| experiment | realism | success | closest approach, m (min / median) | runs with violations "
             "(total) | runs with actuator errors | distinct runs |",
             "|---|---|---:|---:|---:|---:|---:|"]
    for name in EXPERIMENTS:
        out_dir = os.path.join(args.out, name)
        sweep(args.dream, args.source, name, out_dir, args.seeds, args.jobs)
        with open(os.path.join(out_dir, "sweep.csv"), newline="") as f:
            reader = csv.DictReader(f)
            column = realism_column(reader.fieldnames)
            rows = list(reader)
        for preset in PRESETS:
            lines.append(row_for(name, preset, [r for r in rows if r[column] == preset]))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
