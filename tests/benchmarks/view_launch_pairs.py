#!/usr/bin/python3
"""What a `dream view` process adds to a 20-robot lockstep `dream launch`, in interleaved pairs
(issue 37 item 7; docs/performance.md#dream-view).

    tests/integration/netns.sh tests/benchmarks/view_launch_pairs.py --build build --pairs 12

Each pair is two launches of the same run (20 robots on a ring, lockstep, udpm inside the private
network namespace netns.sh makes, --steps steps): one alone on the bus, one with a `dream view`
process watching it (started, and listening, before the launch; no browser unless --browser).
The order inside a pair alternates (without-with, then with-without), so load that comes and goes
on a shared machine hits both sides alike. Reported: each launch's wall time (the `dream launch`
process, start to exit), each pair's ratio with/without, and the median ratio with its spread
(quartiles, min, max) over the pairs, beside the median walls; the view process's own CPU
seconds per run; and the load average when the series began and ended. --perf FILE records the
view process of the last pair with `perf record -g` into FILE (perf report -i FILE);
--baseline-view BIN adds a third side, a view served by another build's dream (the same series:
the same load), and the launch's own CPU seconds are reported too (less disturbed by load).

Nothing here is a pass/fail test; the numbers go to docs/performance.md.
"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "integration"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dreamtest import require_private_netns  # noqa: E402
from view_cost import Browser, ring_config  # noqa: E402

URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")


class Viewer:
    """A `dream view` process on the bus, listening before the launch starts (and a page, if asked)."""

    def __init__(self, dream, folder, browser, perf_file):
        self.out = os.path.join(folder, "view.txt")
        argv = [dream, "view", "--port", "0"]
        self.proc = subprocess.Popen(argv, stdout=open(self.out, "w"), stderr=subprocess.STDOUT)
        self.perf = None
        deadline = time.monotonic() + 20
        while not URL.search(open(self.out).read()):
            if time.monotonic() > deadline or self.proc.poll() is not None:
                sys.exit(f"dream view did not start: {open(self.out).read()[-2000:]}")
            time.sleep(0.01)
        self.browser = None
        if browser:
            self.browser = Browser(folder)
            self.browser.open(URL.search(open(self.out).read()).group(1))
            while not self.browser.page.evaluate("window.dreamView && window.dreamView.state.connected"):
                time.sleep(0.05)
        if perf_file:
            self.perf = subprocess.Popen(["perf", "record", "-g", "-o", perf_file, "-p", str(self.proc.pid)],
                                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            time.sleep(0.5)  # perf attached

    def stop(self):
        """Ends the view; its CPU seconds (user + system, all its threads)."""
        if self.perf:
            self.perf.send_signal(2)
            self.perf.wait()
        if self.browser:
            self.browser.close()
        self.proc.terminate()
        _, _, usage = os.wait4(self.proc.pid, 0)
        return usage.ru_utime + usage.ru_stime


def launch(dream, config, out, steps):
    """One `dream launch`: its wall seconds, and the CPU seconds of its processes (the simulator and
    the agents, which it waits for)."""
    log = open(os.path.join(os.path.dirname(out), "launch.txt"), "w+")
    start = time.monotonic()
    proc = subprocess.Popen([dream, "launch", config, "--out", out, "--overwrite", "--all-steps", "--steps",
                             str(steps)], stdout=log, stderr=subprocess.STDOUT)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    code = os.waitstatus_to_exitcode(status)
    if code not in (0, 3, 5):
        log.seek(0)
        sys.exit(f"dream launch exited {code}: {log.read()[-2000:]}")
    return wall, usage.ru_utime + usage.ru_stime


def quartiles(values):
    q = statistics.quantiles(values, n=4, method="inclusive")
    return q[0], q[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--pairs", type=int, default=12)
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--browser", action="store_true", help="a headless Chromium page on the view too")
    parser.add_argument("--perf", help="perf record the view process of the last pair into this file")
    parser.add_argument("--baseline-view", help="also a view served by this dream binary (another version's), "
                                                "interleaved as a third side")
    args = parser.parse_args()
    require_private_netns()
    dream = os.path.abspath(os.path.join(args.build, "dream"))
    sides = ["without", "with"] + (["baseline"] if args.baseline_view else [])
    binaries = {"with": dream, "baseline": args.baseline_view}
    load_before = os.getloadavg()
    walls = {side: [] for side in sides}
    run_cpu = {side: [] for side in sides}
    view_cpu = {side: [] for side in sides}
    ratios = {side: [] for side in sides[1:]}
    with tempfile.TemporaryDirectory() as folder:
        config = ring_config(os.path.join(folder, "ring20.yaml"), 20, args.steps)
        out = os.path.join(folder, "launch")
        launch(dream, config, out, args.steps)  # warm: the page cache, the libraries mapped once
        for pair in range(args.pairs):
            order = sides if pair % 2 == 0 else sides[::-1]
            wall = {}
            for side in order:
                viewer = None
                if side != "without":
                    perf = args.perf if args.perf and pair == args.pairs - 1 and side == "with" else None
                    viewer = Viewer(binaries[side], folder, args.browser, perf)
                wall[side], cpu = launch(dream, config, out, args.steps)
                if viewer:
                    view_cpu[side].append(viewer.stop())
                walls[side].append(wall[side])
                run_cpu[side].append(cpu)
            for side in sides[1:]:
                ratios[side].append(wall[side] / wall["without"])
            print(f"pair {pair + 1:>2} ({', '.join(order)}): " + ", ".join(
                f"{side} {wall[side]:.2f} s" + (f" ({100 * (ratios[side][-1] - 1):+.1f} %, the view's CPU "
                                               f"{view_cpu[side][-1]:.2f} s)" if side != "without" else "")
                for side in sides), flush=True)
    load_after = os.getloadavg()
    print(f"\n{args.pairs} interleaved {'pairs' if len(sides) == 2 else 'triples'}, 20 robots, lockstep, "
          f"{args.steps} steps{', a Chromium page on the view' if args.browser else ''}"
          f"{'; baseline: ' + args.baseline_view if args.baseline_view else ''}:")
    print("  wall, median: " + ", ".join(f"{side} {statistics.median(walls[side]):.2f} s" for side in sides))
    print("  the launch's own CPU, median: " + ", ".join(f"{side} {statistics.median(run_cpu[side]):.2f} s"
                                                         for side in sides))
    for side in sides[1:]:
        low, high = quartiles(ratios[side]) if len(ratios[side]) > 1 else (ratios[side][0], ratios[side][0])
        print(f"  {side}/without per pair: median {100 * (statistics.median(ratios[side]) - 1):+.1f} %, quartiles "
              f"{100 * (low - 1):+.1f} % to {100 * (high - 1):+.1f} %, min {100 * (min(ratios[side]) - 1):+.1f} %, "
              f"max {100 * (max(ratios[side]) - 1):+.1f} %")
        print(f"  {side}: the view process's CPU per run, median {statistics.median(view_cpu[side]):.2f} s (min "
              f"{min(view_cpu[side]):.2f}, max {max(view_cpu[side]):.2f}), "
              f"{100 * statistics.median(view_cpu[side]) / statistics.median(run_cpu['without']):.1f} % of the "
              f"launch's own CPU")
    print(f"  load average (1, 5, 15 min): {load_before[0]:.1f} {load_before[1]:.1f} {load_before[2]:.1f} at the "
          f"start, {load_after[0]:.1f} {load_after[1]:.1f} {load_after[2]:.1f} at the end")


if __name__ == "__main__":
    main()
