#!/usr/bin/python3
"""A controller written out of tree, against the installed dream (docs/writing-a-controller.md).

    out_of_tree_controller.py --cmake cmake --build build --example docs/examples/out_of_tree_controller

Installs the build tree into a temporary prefix (cmake --install), copies the example
project elsewhere, configures and builds it with find_package(dream) from that prefix only,
runs the INSTALLED `dream run` on the example's config (which names the plugin), and checks
summary.json: the run finished, the `orbit` kind ran, and every robot circles its centre as
the controller says (from the run's log, read with the installed Python types); with --netns, `dream launch` (one agent process per robot, udpm in a
private network namespace) ends the same. Then the installed tools on the run folder (export; check-submission
when numpy is there), the installed `dream spy` finding its jar, and a config naming a
missing plugin (one line, exit 1).
"""
import argparse
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "integration"))
from dreamtest import check, import_types, main, read_events, read_summary  # noqa: E402

SOURCE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

# What the example's orbit.yaml asks for: each robot starts facing +x, so its circle's centre
# is RADIUS_M to the left (+y) of its start.
CENTERS = [(-0.8, 0.0), (0.0, 0.0), (0.8, 0.0)]
RADIUS_M = 0.25
SPEED_MPS = 0.1
STEPS = 600
STEP_S = 0.033
SETTLE_STEPS = 100  # the radius is checked after these


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cmake", required=True)
    parser.add_argument("--build", required=True, help="the dream build tree to install")
    parser.add_argument("--example", required=True, help="docs/examples/out_of_tree_controller")
    parser.add_argument("--generator", default="Unix Makefiles")
    parser.add_argument("--cxx", default="")
    parser.add_argument("--netns", default="", help="tests/integration/netns.sh: also run `dream launch` in it")
    return parser.parse_args()


def installed_files_are_there(prefix):
    for relative in ["bin/dream", "bin/dream-agent", "bin/dream-agent-shared", "lib/libdream_agent_host.so", "lib/libdream_agents.so",
                     "include/dream/agent_host/controller_plugin.h", "include/dream/agents/framework/robot.h",
                     "include/dream/kind_api/controller_kind.h", "lib/libdream_kind_api.so",
                     "include/dream/go_to_goal/kind.h", "lib/libdream_go_to_goal.so",
                     "include/dream/config/config_node.h", "include/dream/robot_poses_t.hpp",
                     "lib/cmake/dream/dreamConfig.cmake", "lib/cmake/dream/dreamConfigVersion.cmake",
                     "lib/cmake/dream/dreamTargets.cmake", "share/dream/java/dream_lcmtypes.jar",
                     "share/dream/python/dream/__init__.py", "share/dream/python/dream/robot_poses_t.py",
                     "share/dream/python/dream_log.py", "share/dream/bridge/run_submission.py",
                     "share/dream/bridge/standin/rps/robotarium.py"]:
        check(os.path.exists(os.path.join(prefix, relative)), f"cmake --install did not install {relative}")


def tools_find_libraries_relative_to_themselves(ctx, prefix, build):
    """The installed tools' RUNPATH is $ORIGIN-relative and never names the build tree; dream-agent, which holds
    the dream libraries it needs, has none and loads no dream library."""
    if shutil.which("readelf") is None:
        return
    for tool in ("dream", "dream-agent-shared", "dream-agent"):
        _, dynamic = ctx.run(["readelf", "-d", os.path.join(prefix, "bin", tool)], expect=0)
        runpath = [line for line in dynamic.splitlines() if "RUNPATH" in line or "RPATH" in line]
        check(os.path.realpath(build) not in dynamic, f"bin/{tool} still names the build tree: {runpath}")
        if tool == "dream-agent":
            check(not runpath and "libdream_" not in dynamic, f"bin/{tool} loads dream libraries: {dynamic}")
        else:
            check(runpath and "$ORIGIN" in runpath[0], f"bin/{tool} has no $ORIGIN run path: {runpath}")


def build_example(ctx, args, prefix):
    project = ctx.path("orbit_project")
    shutil.copytree(args.example, project, ignore=shutil.ignore_patterns("build"))
    configure = [args.cmake, "-S", project, "-B", os.path.join(project, "build"), "-G", args.generator,
                 "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_PREFIX_PATH=" + prefix,
                 "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF"]
    if args.cxx:
        configure.append("-DCMAKE_CXX_COMPILER=" + args.cxx)
    ctx.run(configure, timeout=120, expect=0)
    with open(os.path.join(project, "build", "CMakeCache.txt")) as f:
        cache = f.read()
    check(f"dream_DIR:PATH={prefix}/lib/cmake/dream" in cache,
          "find_package(dream) did not find the installed package in " + prefix)
    ctx.run([args.cmake, "--build", os.path.join(project, "build"), "-j2"], timeout=180, expect=0)
    check(os.path.isfile(os.path.join(project, "build", "liborbit_controller.so")), "the plugin was not built")
    return project


def laps_and_radius_error(run_dir, types):
    """From the run's log: the laps the slowest robot drove counter-clockwise around its centre,
    and how far any robot was from its circle after SETTLE_STEPS."""
    turned_rad = [0.0] * len(CENTERS)
    last_angle_rad = [None] * len(CENTERS)
    last_step = -1
    max_radius_error_m = 0.0
    for event in read_events(os.path.join(run_dir, "run.lcmlog")):
        if event.channel != "DREAM_POSES":
            continue
        poses = types.robot_poses_t.decode(event.data)
        if poses.step <= last_step:
            continue  # the world resends a step while it waits for commands
        last_step = poses.step
        for robot, (cx, cy) in enumerate(CENTERS):
            dx, dy = poses.x[robot] - cx, poses.y[robot] - cy
            angle_rad = math.atan2(dy, dx)
            if last_angle_rad[robot] is not None:
                turned_rad[robot] += math.remainder(angle_rad - last_angle_rad[robot], 2 * math.pi)
            last_angle_rad[robot] = angle_rad
            if poses.step >= SETTLE_STEPS:
                max_radius_error_m = max(max_radius_error_m, abs(math.hypot(dx, dy) - RADIUS_M))
    check(last_step >= 0, f"{run_dir}/run.lcmlog has no poses")
    return min(turned_rad) / (2 * math.pi), max_radius_error_m


def robots_orbit_as_told(summary, run_dir, types):
    check(summary["end"] == "finished", f"the run ended {summary['end']}: {summary.get('reason')}")
    check(summary["steps"] == STEPS, f"{summary['steps']} steps, expected {STEPS}")
    check(summary["verdict"] == "clean", f"verdict {summary['verdict']}: {summary.get('violations')}")
    metrics = summary["metrics"]
    check(metrics.get("kind") == "orbit", f"metrics are not the orbit kind's: {metrics}")
    # One class, no metrics of its own: the safety metrics every kind gets.
    check(metrics.get("min_pairwise_distance_m", 0.0) > 0.25, f"robots came close: {metrics}")
    min_laps, max_radius_error_m = laps_and_radius_error(run_dir, types)
    expected_laps = SPEED_MPS * STEPS * STEP_S / (2 * math.pi * RADIUS_M)
    check(0.85 * expected_laps <= min_laps <= 1.02 * expected_laps,
          f"the slowest robot drove {min_laps:.3f} laps, expected about {expected_laps:.3f}")
    check(max_radius_error_m < 0.02, f"robots left their circles by {max_radius_error_m:.3f} m")
    for robot, (x, y, _) in enumerate(summary["final_poses"]):
        distance = math.hypot(x - CENTERS[robot][0], y - CENTERS[robot][1])
        check(abs(distance - RADIUS_M) < 0.02, f"robot {robot} ends {distance:.3f} m from its centre")


def test(ctx):
    args = parse_args()
    prefix = ctx.path("prefix")
    ctx.run([args.cmake, "--install", args.build, "--prefix", prefix], timeout=60, expect=0)
    installed_files_are_there(prefix)
    tools_find_libraries_relative_to_themselves(ctx, prefix, args.build)
    dream = os.path.join(prefix, "bin", "dream")

    # A Python controller runs with the installed tool alone (its runtime under share/dream).
    python_dir = ctx.path("python_run")
    ctx.run([dream, "run", os.path.join(SOURCE_DIR, "config", "go_to_goal_python.yaml"), "--out", python_dir, "-q"],
            timeout=60, expect=0)
    check(read_summary(python_dir)["robots_done"] == list(range(8)), "the installed dream's Python go_to_goal "
                                                                     "did not bring every robot to its goal")

    project = build_example(ctx, args, prefix)
    run_dir = ctx.path("orbit_run")
    ctx.run([dream, "run", os.path.join(project, "orbit.yaml"), "--out", run_dir, "-q"], timeout=60, expect=0)
    summary = read_summary(run_dir)
    robots_orbit_as_told(summary, run_dir, import_types(os.path.join(prefix, "share", "dream", "python")))
    if args.netns:
        # One dream-agent process per robot over udpm, each loading the plugin: the same run.
        launch_dir = ctx.path("orbit_launch")
        code, output = ctx.run([args.netns, dream, "launch", os.path.join(project, "orbit.yaml"), "--out", launch_dir,
                                "-q"], timeout=60)
        if code != 77:
            check(code == 0, f"dream launch exited {code}: {output[-400:]}")
            check(read_summary(launch_dir)["final_poses"] == summary["final_poses"],
                  "dream launch and dream run of the plugin's kind end with different poses")

    # The run folder alone is enough for the other tools, plugin included.
    export_dir = ctx.path("orbit_export")
    ctx.run([dream, "export", run_dir, "--out", export_dir, "-q"], timeout=60, expect=0)
    if subprocess.run([sys.executable, "-c", "import numpy"], capture_output=True).returncode == 0:
        ctx.run([dream, "check-submission", export_dir, "--standin", "--out", ctx.path("orbit_check"), "-q"],
                timeout=120, expect=0)

    _, spy = ctx.run([dream, "spy", "--print"], expect=0)
    check(os.path.join(prefix, "share", "dream", "java", "dream_lcmtypes.jar") in spy,
          "the installed dream spy does not use the installed jar: " + spy)
    ctx.run([os.path.join(prefix, "bin", "dream-agent"), "--help"], expect=0)
    # The installed Python types and reader import from share/dream/python alone.
    env = dict(os.environ, PYTHONPATH=os.path.join(prefix, "share", "dream", "python"), PYTHONDONTWRITEBYTECODE="1")
    python = subprocess.run([sys.executable, "-c", "import dream, dream_log; print(dream.robot_poses_t.__name__)"],
                            capture_output=True, text=True, env=env, cwd=ctx.dir)
    check(python.returncode == 0 and "robot_poses_t" in python.stdout,
          "the installed Python files do not import: " + python.stderr.strip()[-300:])

    # A config naming a plugin that is not there: one line naming the entry and the path.
    with open(os.path.join(project, "orbit.yaml")) as f:
        text = f.read()
    broken = os.path.join(project, "broken.yaml")
    with open(broken, "w") as f:
        f.write(text.replace("build/liborbit_controller.so", "build/libnothing.so"))
    code, output = ctx.run([dream, "run", broken, "--out", ctx.path("broken_run"), "-q"])
    lines = output.strip().splitlines()
    check(code == 1 and len(lines) == 1, f"a missing plugin gave exit {code} and {len(lines)} lines: {output}")
    line = 1 + next(i for i, text_line in enumerate(text.splitlines()) if text_line.startswith("plugins:"))
    expected = f"broken.yaml:{line}: plugins[0]: {os.path.join(project, 'build', 'libnothing.so')}: no such file"
    check(expected in lines[0], f"the error does not name the entry and the path ({expected}): {lines[0]}")
    check(not os.path.exists(ctx.path("broken_run")), "a refused run made its output folder")


if __name__ == "__main__":
    main(test)
