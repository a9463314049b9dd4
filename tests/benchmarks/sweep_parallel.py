#!/usr/bin/python3
"""Wall time of a sweep with one run at a time and with one run per core.

    tests/benchmarks/sweep_parallel.py --build build config/hrvo_circle.yaml --seeds 1-20

Runs `dream sweep CONFIG --seeds SEEDS --jobs 1` and `--jobs N` (N = cores), best of
--repeat each, prints both wall times, the speed-up and the CPU time of all runs, and
checks that both sweeps give the same table (every column but the wall times): the
runs are independent processes, so running them side by side must not change them.
Numbers go to docs/sweeps.md and docs/performance.md; nothing here is a pass/fail test
of speed. Lockstep runs hand every step between threads, so they slow down badly when
other programs load the machine: measure on an idle one (the load average is printed).
"""
import argparse
import csv
import os
import resource
import subprocess
import sys
import tempfile
import time


def sweep(dream, config, seeds, jobs, out):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.monotonic()
    result = subprocess.run([dream, "-q", "sweep", config, "--seeds", seeds, "--jobs", str(jobs), "--out", out],
                            capture_output=True, text=True, check=False)
    wall_s = time.monotonic() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if result.returncode != 0:
        sys.exit(f"dream sweep --jobs {jobs} exited {result.returncode}: {result.stdout[-400:]}{result.stderr[-400:]}")
    cpu_s = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "sweep.csv"), newline="") as f:
        rows = [{k: v for k, v in row.items() if k != "wall_time_s"} for row in csv.DictReader(f)]
    return wall_s, cpu_s, rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config")
    parser.add_argument("--build", default="build")
    parser.add_argument("--seeds", default="1-20")
    parser.add_argument("--repeat", type=int, default=3, help="sweeps per --jobs value; the fastest is reported")
    args = parser.parse_args()
    dream = os.path.join(args.build, "dream")
    cores = os.cpu_count() or 1
    print(f"load average before: {os.getloadavg()[0]:.2f} on {cores} cores")
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for jobs in (1, cores):
            best = None
            for i in range(args.repeat):
                wall_s, cpu_s, rows = sweep(dream, args.config, args.seeds, jobs, os.path.join(tmp, f"j{jobs}_{i}"))
                if best is None or wall_s < best[0]:
                    best = (wall_s, cpu_s, rows)
            results[jobs] = best
            print(f"--jobs {jobs}: {best[0]:.2f} s wall, {best[1]:.2f} s CPU of all runs, {len(best[2])} runs")
    if results[1][2] != results[cores][2]:
        sys.exit("the two sweeps gave different tables")
    successes = sum(row["success"] == "true" for row in results[1][2])
    print(f"speed-up with {cores} jobs: {results[1][0] / results[cores][0]:.2f}x; same table "
          f"({successes} of {len(results[1][2])} runs successful)")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
