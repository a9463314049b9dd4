#!/usr/bin/python3
"""Does `dream view` keep up with a 30 Hz stream of 100 robots, and what does its page cost?
(docs/performance.md#dream-view)

    tests/integration/netns.sh tests/benchmarks/view_stream.py --build build
    tests/integration/netns.sh tests/benchmarks/view_stream.py --build build --robots 20 --fps 15

This isolates the page's cost from a run's (view_cost.py's part 3 watches a real 100-robot run,
`sim_only: true`): a small publisher here sends what a world sends each step (DREAM_OBSTACLES, DREAM_STATUS,
DREAM_POSES of --robots robots driving circles; lcmtypes' messages, udpm inside the private
network namespace netns.sh makes) at --rate steps a second for --seconds, then a FINISHED status.
`dream view` (and its page in a headless Chromium) watches it. Reported: the steps published and
at what rate, the frames the page received and drew, whether it shows the last step, and the CPU
time spent by the view's process and by Chromium while the stream ran: all its processes, its
renderer process (the page's own), and the page's main-thread task time (devtools
Performance.getMetrics' TaskDuration), and Chromium's busiest threads by process (from /proc).
--profile FILE also records the page's devtools CPU profile and prints its costliest functions;
--screenshot FILE keeps a picture of the page at the end.
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
from devtools import Page, chromium_argv, devtools_port  # noqa: E402
from dreamtest import Udpm, import_types, require_private_netns  # noqa: E402

URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")
TICKS = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pids):
    """User + system CPU seconds of the processes `pids` so far (those still there)."""
    total = 0
    for pid in pids:
        try:
            with open(f"/proc/{pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            total += int(fields[11]) + int(fields[12])
        except OSError:
            pass
    return total / TICKS


def process_role(pid):
    """Chromium's --type of process `pid` (renderer, gpu-process, utility, zygote), else "browser"."""
    try:
        with open(f"/proc/{pid}/cmdline", "rb") as f:
            found = re.search(rb"--type=([a-z-]+)", f.read())
    except OSError:
        return "gone"
    return found.group(1).decode() if found else "browser"


def thread_seconds(pids):
    """User + system CPU seconds so far of each thread of `pids`, by process role and thread name
    (summed over threads of one name: Chromium's raster workers share theirs)."""
    by_name = {}
    for pid in pids:
        try:
            tasks = os.listdir(f"/proc/{pid}/task")
        except OSError:
            continue
        role = process_role(pid)
        for tid in tasks:
            try:
                with open(f"/proc/{pid}/task/{tid}/stat") as f:
                    text = f.read()
            except OSError:
                continue
            name = role + "/" + text[text.index("(") + 1:text.rindex(")")]
            fields = text.rsplit(")", 1)[1].split()
            by_name[name] = by_name.get(name, 0) + (int(fields[11]) + int(fields[12])) / TICKS
    return by_name


def process_tree(root):
    """`root` and every process descended from it (Chromium's zygote and renderers start their own
    sessions, so the tree is followed by parent)."""
    parents = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    parents[int(entry)] = int(f.read().rsplit(")", 1)[1].split()[1])
            except OSError:
                pass
    tree, grew = {root}, True
    while grew:
        more = {pid for pid, parent in parents.items() if parent in tree and pid not in tree}
        tree |= more
        grew = bool(more)
    return sorted(tree)


def renderers(pids):
    """Those of `pids` that are Chromium renderer processes (the page's own: script, layout, drawing)."""
    found = []
    for pid in pids:
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                if b"--type=renderer" in f.read():
                    found.append(pid)
        except OSError:
            pass
    return found


def task_seconds(page):
    """The page's main-thread task time so far (devtools Performance.getMetrics' TaskDuration)."""
    metrics = page.call("Performance.getMetrics")["metrics"]
    return next(m["value"] for m in metrics if m["name"] == "TaskDuration")


def print_profile(profile, path, top=25):
    """Writes a devtools Profiler profile to `path` and prints where the page's time went: self time
    per function (and per built-in: (program) is the browser's own work outside script, painting
    the canvas included; (garbage collector); (idle))."""
    with open(path, "w") as f:
        json.dump(profile, f)
    nodes = {node["id"]: node for node in profile["nodes"]}
    deltas = profile.get("timeDeltas", [])
    self_us = {}
    for node_id, delta in zip(profile.get("samples", []), deltas):
        frame = nodes[node_id]["callFrame"]
        name = f"{frame['functionName'] or '(anonymous)'} {os.path.basename(frame['url'])}:{frame['lineNumber'] + 1}"
        self_us[name] = self_us.get(name, 0) + delta
    total = sum(self_us.values()) or 1
    busy = total - self_us.get("(idle) :0", 0)
    print(f"profile ({path}): {total / 1e6:.2f} s sampled, {busy / 1e6:.2f} s not idle; self time, not idle:")
    for name, us in sorted(self_us.items(), key=lambda item: -item[1])[:top]:
        if name != "(idle) :0":
            print(f"  {100 * us / busy:5.1f} %  {us / 1e3:8.1f} ms  {name}")


def messages(dream, robots, step, run_id, rate):
    """One step of a world: obstacles, status, poses (robots on a grid, each driving a small circle)."""
    t = step / rate
    poses = dream.robot_poses_t()
    poses.utime, poses.step, poses.run_id, poses.num_robots = int(step * 33000), step, run_id, robots
    columns = math.ceil(math.sqrt(robots * 3.2 / 2))
    xs, ys, ths = [], [], []
    for i in range(robots):
        cx = -1.5 + 3.0 * (i % columns + 0.5) / columns
        cy = -0.9 + 1.8 * (i // columns + 0.5) / math.ceil(robots / columns)
        a = 0.5 * t + i
        xs.append(cx + 0.05 * math.cos(a))
        ys.append(cy + 0.05 * math.sin(a))
        ths.append(math.atan2(math.sin(a + math.pi / 2), math.cos(a + math.pi / 2)))
    poses.x, poses.y, poses.theta = xs, ys, ths
    poses.v, poses.w = [0.025] * robots, [0.5] * robots
    status = dream.run_status_t()
    status.utime, status.step, status.run_id, status.num_robots = poses.utime, step, run_id, robots
    status.state = dream.run_status_t.RUNNING
    status.detail = "view_stream benchmark"
    obstacles = dream.obstacles_t()
    obstacles.utime, obstacles.step, obstacles.run_id = poses.utime, step, run_id
    return obstacles, status, poses


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--robots", type=int, default=100)
    parser.add_argument("--rate", type=float, default=30.0, help="steps a second")
    parser.add_argument("--seconds", type=float, default=20.0)
    parser.add_argument("--fps", type=int, default=None, help="dream view --fps (default: its own)")
    parser.add_argument("--no-browser", action="store_true")
    parser.add_argument("--page-eval", default="", help="JavaScript run in the page before the stream (to try variants)")
    parser.add_argument("--screenshot", default="", help="a PNG of the page at the stream's end, here")
    parser.add_argument("--profile", default="", help="write the page's CPU profile of the stream here (devtools "
                        "Profiler, a .cpuprofile Chromium's DevTools open) and print its costliest functions")
    args = parser.parse_args()
    require_private_netns()
    dream = import_types(os.path.join(args.build, "python"))
    binary = os.path.abspath(os.path.join(args.build, "dream"))
    with tempfile.TemporaryDirectory() as folder:
        out = open(os.path.join(folder, "view.txt"), "w+")
        argv = [binary, "view", "--port", "0"] + (["--fps", str(args.fps)] if args.fps else [])
        view = subprocess.Popen(argv, stdout=out, stderr=subprocess.STDOUT)
        chrome, page = None, None
        try:
            deadline = time.monotonic() + 10
            while not URL.search(open(out.name).read()):
                if time.monotonic() > deadline or view.poll() is not None:
                    sys.exit(f"dream view printed no address: {open(out.name).read()}")
                time.sleep(0.05)
            if not args.no_browser:
                data = os.path.join(folder, "chrome")
                chrome = subprocess.Popen(chromium_argv(data, URL.search(open(out.name).read()).group(1)),
                                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
                page = Page(devtools_port(data))
                while not page.evaluate("window.dreamView && window.dreamView.state.connected"):
                    time.sleep(0.05)
                if args.page_eval:
                    page.evaluate(args.page_eval)
                time.sleep(1.0)  # the page settled: idle costs are not the stream's
            bus = Udpm()
            steps = int(args.seconds * args.rate)
            run_id = int(time.time() * 1e6)
            chrome_pids = process_tree(chrome.pid) if chrome else []
            renderer_pids = renderers(chrome_pids)
            if page:
                page.call("Performance.enable")
                if args.profile:
                    page.call("Profiler.enable")
                    page.call("Profiler.setSamplingInterval", interval=200)
                    page.call("Profiler.start")
            view_cpu, chrome_cpu = cpu_seconds([view.pid]), cpu_seconds(chrome_pids)
            renderer_cpu, tasks = cpu_seconds(renderer_pids), task_seconds(page) if page else 0.0
            threads = thread_seconds(chrome_pids)
            start = time.monotonic()
            for step in range(steps + 1):
                time.sleep(max(0.0, start + step / args.rate - time.monotonic()))
                for channel, message in zip(("DREAM_OBSTACLES", "DREAM_STATUS", "DREAM_POSES"),
                                            messages(dream, args.robots, step, run_id, args.rate)):
                    bus.publish(channel, message.encode())
            elapsed = time.monotonic() - start
            _, status, _ = messages(dream, args.robots, steps, run_id, args.rate)
            status.state = dream.run_status_t.FINISHED
            bus.publish("DREAM_STATUS", status.encode())
            view_cpu = cpu_seconds([view.pid]) - view_cpu
            chrome_cpu = cpu_seconds(chrome_pids) - chrome_cpu
            renderer_cpu = cpu_seconds(renderer_pids) - renderer_cpu
            threads = {name: cpu - threads.get(name, 0) for name, cpu in thread_seconds(chrome_pids).items()}
            tasks = task_seconds(page) - tasks if page else 0.0
            if page and args.profile:
                print_profile(page.call("Profiler.stop")["profile"], args.profile)
            print(f"stream: {args.robots} robots, {steps + 1} steps in {elapsed:.2f} s "
                  f"({steps / elapsed:.1f} steps/s), dream view --fps {args.fps or 'default'}")
            print(f"dream view's process: {view_cpu:.2f} s CPU ({100 * view_cpu / elapsed:.1f} % of a core)")
            if page:
                time.sleep(1.0)
                state = page.evaluate("window.dreamView.state")
                if args.screenshot:
                    page.screenshot(args.screenshot)
                drawn = page.evaluate("window.dreamView.drawn")
                print(f"page: received {state['frames']} frames ({state['frames'] / elapsed:.1f}/s), drew "
                      f"{drawn} ({drawn / elapsed:.1f}/s), shows step {state['step']} of {steps} "
                      f"({'the last' if state['step'] == steps else 'NOT the last'}), {len(state['robots'])} "
                      f"robots, state '{state.get('state')}'")
                print(f"Chromium (all its processes): {chrome_cpu:.2f} s CPU ({100 * chrome_cpu / elapsed:.1f} % "
                      f"of a core)")
                print(f"the page's renderer process ({len(renderer_pids)}): {renderer_cpu:.2f} s CPU "
                      f"({100 * renderer_cpu / elapsed:.1f} % of a core); its main thread's tasks (devtools "
                      f"TaskDuration) {tasks:.2f} s ({100 * tasks / elapsed:.1f} %)")
                busiest = sorted(((cpu, name) for name, cpu in threads.items() if cpu > 0), reverse=True)[:8]
                print("Chromium's busiest threads (all its processes): " +
                      ", ".join(f"{name} {100 * cpu / elapsed:.1f} %" for cpu, name in busiest))
            bus.close()
        finally:
            if page:
                page.close()
            if chrome:
                os.killpg(chrome.pid, 15)
                chrome.wait()
            view.terminate()
            view.wait()


if __name__ == "__main__":
    main()
