#!/usr/bin/python3
"""What `dream view` costs the runs it watches, and whether it keeps up (docs/performance.md).

    tests/benchmarks/view_cost.py --build build            # dream run with and without --view
    tests/integration/netns.sh tests/benchmarks/view_cost.py --build build --udpm   # dream launch too

1. `dream run` (one process, memq) of 20 robots (go to goal on a ring), lockstep, --all-steps:
   without the view, with --view --pace 0 (the view's handler in the run's own loop), and with
   --view and a headless Chromium page drawing it (opened when the run prints its address, so
   Chromium's start-up overlaps the run). Runs interleaved, best of --repeat, steps/s from
   summary.json.
2. With --udpm (inside a private network namespace): `dream launch` of the same config (the
   simulator and 20 agent processes) without and with a `dream view` process on the bus and a
   Chromium page drawing it (opened and settled before the run starts, as a user's page is),
   and with pages of `dream view --fps N` for each N of --fps.
3. A real-time run of 100 robots (`sim_only: true`: the Robotarium's simulator stops at 50) with
   --view and a page: whether the run kept real time, how many frames the page received and drew
   a second, and whether it showed the last step.

Nothing here is a pass/fail test; the numbers go to docs/performance.md.
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "integration"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from devtools import Page, chromium_argv, devtools_port  # noqa: E402
from dreamtest import TestFailure  # noqa: E402
from view_stream import cpu_seconds, process_tree  # noqa: E402

URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")


def ring_config(path, robots, steps, mode="lockstep"):
    """Robots on a ring driving to a smaller one (up to 20), or on a 10-column grid (columns 0.3 m, rows
    0.2 m apart, as tests/integration/sim_only_hundred_robots.py) each driving 0.1 m ahead (+x)."""
    starts, goals = [], []
    for i in range(robots):
        if robots <= 20:
            a = 2 * math.pi * i / robots
            starts.append(f"  - [{0.9 * math.cos(a) * 1.5:.3f}, {0.9 * math.sin(a):.3f}, {a + math.pi:.3f}]")
            goals.append(f"    - [{0.5 * math.cos(a) * 1.5:.3f}, {0.5 * math.sin(a):.3f}]")
        else:
            x, y = -1.35 + 0.3 * (i % 10), -0.9 + 0.2 * (i // 10)
            starts.append(f"  - [{x:.3f}, {y:.3f}, 0.0]")
            goals.append(f"    - [{x + 0.1:.3f}, {y:.3f}]")
    with open(path, "w") as f:
        f.write(f"name: ring{robots}\nseed: 1\nrobots: {robots}\nsteps: {steps}\nstop_when_done: false\n"
                + ("sim_only: true\n" if robots > 50 else "") +
                f"world:\n  mode: {mode}\n  start_timeout_s: 60\ninitial_poses:\n" + "\n".join(starts) +
                "\ncontroller:\n  kind: go_to_goal\n  gain: 0.8\n  max_speed_mps: 0.15\n  tolerance_m: 0.02\n"
                "  goals:\n" + "\n".join(goals) + "\n")
    return path


class Browser:
    """A headless Chromium showing `url` once a process prints it."""

    def __init__(self, folder):
        self.folder = folder
        self.proc = None
        self.page = None

    def open(self, url):
        data = os.path.join(self.folder, f"chrome{time.monotonic_ns()}")
        self.proc = subprocess.Popen(chromium_argv(data, url), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        self.page = Page(devtools_port(data))

    def cpu_s(self):
        """CPU seconds Chromium's processes have spent so far."""
        return cpu_seconds(process_tree(self.proc.pid)) if self.proc else 0.0

    def state(self):
        """What the page drew (None when the run ended before the page had loaded)."""
        return self.page.evaluate("window.dreamView ? Object.assign({drawn: window.dreamView.drawn}, "
                                  "window.dreamView.state) : null")

    def close(self):
        if self.page:
            self.page.close()
        if self.proc:
            self.proc.terminate()
            self.proc.wait()


def run_and_watch(argv, folder, watch, url_from=None):
    """Runs argv; with watch, opens a page on the URL the process (or `url_from`) prints first."""
    log = open(os.path.join(folder, "out.txt"), "w+")
    proc = subprocess.Popen(argv, stdout=log, stderr=subprocess.STDOUT)
    browser = Browser(folder)
    try:
        if watch:
            source = url_from or log.name
            deadline = time.monotonic() + 10
            while time.monotonic() < deadline:
                with open(source) as f:
                    found = URL.search(f.read())
                if found:
                    try:
                        browser.open(found.group(1))
                    except (TestFailure, OSError):  # the run ended (and its page went) while Chromium started
                        pass
                    break
                time.sleep(0.01)
        _, status, usage = os.wait4(proc.pid, 0)  # with the CPU time of the run's processes (and their children)
        proc.returncode = code = os.waitstatus_to_exitcode(status)
        run_and_watch.cpu_s = usage.ru_utime + usage.ru_stime
        try:
            state = browser.state() if browser.page else None
        except (TestFailure, OSError):  # a short run ends before its page has loaded
            state = None
    finally:
        browser.close()
    if code not in (0, 3, 5):
        log.seek(0)
        sys.exit(f"{' '.join(argv)} exited {code}: {log.read()[-2000:]}")
    return state


def steps_per_second(out_dir):
    """The run's loop speed, and the CPU seconds its processes spent per 1,000 steps."""
    with open(os.path.join(out_dir, "summary.json")) as f:
        summary = json.load(f)
    return summary["steps_per_second"], run_and_watch.cpu_s * 1000 / summary["steps"]


def compare(name, variants, repeat):
    """Interleaved runs: the best speed of each, and the median CPU time of the run's own processes
    (less disturbed by other load on the machine than the wall time)."""
    speeds = {label: [] for label, _ in variants}
    cpu = {label: [] for label, _ in variants}
    for _ in range(repeat):
        for label, run in variants:
            speed, cpu_s = run()
            speeds[label].append(speed)
            cpu[label].append(cpu_s)
    base_speed = max(speeds[variants[0][0]])
    base_cpu = sorted(cpu[variants[0][0]])[repeat // 2]
    base_median = sorted(speeds[variants[0][0]])[repeat // 2]
    print(f"\n{name} (best and median of {repeat} steps/s; median CPU s of the run's processes per 1,000 steps):")
    for label, _ in variants:
        speed, cpu_s = max(speeds[label]), sorted(cpu[label])[repeat // 2]
        median = sorted(speeds[label])[repeat // 2]
        print(f"  {label:<42} {speed:>6.0f} {100 * (speed / base_speed - 1):+6.1f} %   {median:>6.0f} "
              f"{100 * (median / base_median - 1):+6.1f} %   CPU {cpu_s:.3f} s  {100 * (cpu_s / base_cpu - 1):+6.1f} %")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--udpm", action="store_true", help="also dream launch (run inside tests/integration/netns.sh)")
    parser.add_argument("--only-udpm", action="store_true", help="only dream launch")
    parser.add_argument("--baseline-view", help="dream launch: also a page served by this dream binary's view "
                                                "(another version's page, to compare)")
    parser.add_argument("--no-bare-view", action="store_true", help="dream launch: skip the view without a browser")
    parser.add_argument("--fps", type=int, nargs="*", default=[],
                        help="dream launch: also a page with dream view --fps each of these")
    args = parser.parse_args()
    dream = os.path.abspath(os.path.join(args.build, "dream"))
    with tempfile.TemporaryDirectory() as folder:
        config = ring_config(os.path.join(folder, "ring20.yaml"), 20, args.steps)

        def embedded(view, watch):
            out = os.path.join(folder, "run")
            extra = ["--view", "--pace", "0", "--view-port", "0"] if view else []
            run_and_watch([dream, "run", config, "--out", out, "--overwrite", "--all-steps"] + extra, folder, watch)
            return steps_per_second(out)

        if not args.only_udpm:
            compare("dream run, 20 robots, lockstep, memq", [
                ("without the view", lambda: embedded(False, False)),
                ("--view, no browser", lambda: embedded(True, False)),
                ("--view, a headless Chromium drawing it", lambda: embedded(True, True)),
            ], args.repeat)

        if args.udpm or args.only_udpm:
            launch_steps = 3000

            def launched(view, watch, fps=None, viewer_binary=None):
                out = os.path.join(folder, "launch")
                viewer = None
                url_file = os.path.join(folder, "view.txt")
                if view:
                    viewer = subprocess.Popen([viewer_binary or dream, "view", "--port", "0"] +
                                              (["--fps", str(fps)] if fps else []),
                                              stdout=open(url_file, "w"), stderr=subprocess.STDOUT)
                browser = Browser(folder)
                try:
                    if watch:  # open and settled before the run: a user's page is, and starting Chromium is not drawing
                        deadline = time.monotonic() + 10
                        while not URL.search(open(url_file).read()) and time.monotonic() < deadline:
                            time.sleep(0.01)
                        browser.open(URL.search(open(url_file).read()).group(1))
                        while not browser.page.evaluate("window.dreamView && window.dreamView.state.connected"):
                            time.sleep(0.05)
                        time.sleep(1.0)
                    chrome_before = browser.cpu_s()
                    run_and_watch([dream, "launch", config, "--out", out, "--overwrite", "--all-steps",
                                   "--steps", str(launch_steps)], folder, False)
                    if watch:
                        which = "the baseline's page" if viewer_binary else f"--fps {fps or 'default'}"
                        print(f"    Chromium ({which}): {browser.cpu_s() - chrome_before:.2f} s CPU during the run "
                              f"of {launch_steps} steps", flush=True)
                finally:
                    browser.close()
                    if viewer:
                        viewer.terminate()
                        viewer.wait()
                return steps_per_second(out)

            compare("dream launch, 20 robots, lockstep, udpm", [
                ("without the view", lambda: launched(False, False)),
            ] + ([] if args.no_bare_view else [("dream view on the bus, no browser", lambda: launched(True, False))]) + [
                ("dream view on the bus, a Chromium page", lambda: launched(True, True)),
            ] + [(f"dream view --fps {fps}, a Chromium page", lambda fps=fps: launched(True, True, fps))
                 for fps in args.fps] +
                ([("the page of --baseline-view", lambda: launched(True, True, None, args.baseline_view))]
                 if args.baseline_view else []), args.repeat)

        if args.only_udpm:
            return
        big = ring_config(os.path.join(folder, "grid100.yaml"), 100, 600, mode="realtime")
        out = os.path.join(folder, "realtime")
        state = run_and_watch([dream, "run", big, "--out", out, "--overwrite", "--all-steps", "--view",
                               "--view-port", "0"], folder, True)
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        wall_s = summary["steps"] / summary["steps_per_second"]
        print(f"\nreal time, 100 robots (sim_only), {summary['steps']} steps at {summary['steps_per_second']:.1f} "
              f"steps/s ({summary['verdict']}) with --view and a page: the page received {state['frames']} "
              f"frames ({state['frames'] / wall_s:.1f}/s), drew {state['drawn']}, showed step {state['step']} "
              f"(the run's last: {summary['steps']}), {len(state['robots'])} robots")


if __name__ == "__main__":
    main()
