#!/usr/bin/python3
"""spy_print_command: `dream spy --print` names a java command that can really start lcm-spy with
the dream types.

Checks the printed lines of `dream spy --print --log LOG`: `java -cp CP lcm.spy.Spy --lcm-url=URL`
with lcm.jar, jchart2d.jar and the build's types jar on CP (all present), then
`lcm-logplayer --lcm-url=URL LOG` on the same loopback-only (ttl=0) URL; that CP really holds
lcm.spy.Spy and the dream types (javap); that without --log the spy listens on $LCM_DEFAULT_URL;
and that a missing log is refused, naming it. A GUI cannot run here: only when xvfb-run exists is
the printed command started under Xvfb for 5 s, and it must not die with an exception.

Usage: netns.sh spy_print_command.py --dream BIN --source DIR --types-jar JAR
"""

import os
import shlex
import shutil
import subprocess

from dreamtest import argument_parser, check, main, require_private_netns


def parse_spy_line(line):
    """(classpath entries, url) of `java -cp CP lcm.spy.Spy --lcm-url=URL`."""
    words = shlex.split(line)  # the printed command is shell-quoted, ready to paste
    check(len(words) == 5 and words[0] == "java" and words[1] == "-cp" and words[3] == "lcm.spy.Spy"
          and words[4].startswith("--lcm-url="),
          f"expected `java -cp CLASSPATH lcm.spy.Spy --lcm-url=URL`, got `{line}`")
    return words[2].split(":"), words[4][len("--lcm-url="):]


def test(ctx):
    parser = argument_parser()
    parser.add_argument("--types-jar", required=True)
    args = parser.parse_args()

    run = ctx.path("run")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", run,
             "--steps", "5"], expect=0)
    log = os.path.join(run, "run.lcmlog")

    env = dict(os.environ)
    env.pop("DREAM_TYPES_JAR", None)
    result = subprocess.run([args.dream, "spy", "--print", "--log", log], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=10, env=env)
    check(result.returncode == 0, f"dream spy --print --log exited {result.returncode}: {result.stdout.strip()}")
    check(all(line == line.rstrip() for line in result.stdout.splitlines()),
          f"printed command lines end in blanks: {result.stdout!r}")
    lines = [line.strip() for line in result.stdout.strip().splitlines()]
    check(len(lines) == 2, f"expected two command lines (spy, logplayer), got {len(lines)}: {lines}")
    classpath, url = parse_spy_line(lines[0])
    names = [os.path.basename(entry) for entry in classpath]
    for jar in ["lcm.jar", "jchart2d.jar", os.path.basename(args.types_jar)]:
        check(jar in names, f"spy classpath {classpath} lacks {jar}")
    for entry in classpath:
        check(os.path.isfile(entry), f"spy classpath entry {entry} does not exist")
    types_entry = classpath[names.index(os.path.basename(args.types_jar))]
    check(os.path.realpath(types_entry) == os.path.realpath(args.types_jar),
          f"spy uses {types_entry}, not the build's types jar {args.types_jar}")
    check(url.startswith("udpm://") and "ttl=0" in url, f"a replayed log must stay on loopback (ttl=0): {url}")
    player = shlex.split(lines[1])
    check(player == ["lcm-logplayer", "--lcm-url=" + url, log],
          f"expected `lcm-logplayer --lcm-url={url} {log}`, got `{lines[1]}`")

    # A run folder stands for its run.lcmlog, as for every command that reads a log.
    result = subprocess.run([args.dream, "spy", "--print", "--log", run], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, timeout=10, env=env)
    lines = result.stdout.strip().splitlines()
    check(result.returncode == 0 and len(lines) == 2 and shlex.split(lines[1])[-1] == log,
          f"dream spy --print --log RUN_FOLDER should play {log}: exit {result.returncode}, {result.stdout.strip()!r}")

    javap = shutil.which("javap")
    check(javap, "javap not found (apt-get install default-jdk-headless)")
    code, text = ctx.run([javap, "-cp", ":".join(classpath), "lcm.spy.Spy", "dream.robot_poses_t",
                          "dream.run_status_t", "info.monitorenter.gui.chart.Chart2D"], timeout=60)
    check(code == 0, f"the spy classpath does not hold lcm.spy.Spy, jchart2d and the dream types: "
                     f"{text.strip().splitlines()[-1] if text.strip() else code}")

    live_url = "udpm://239.255.76.67:7669?ttl=0"
    env["LCM_DEFAULT_URL"] = live_url
    result = subprocess.run([args.dream, "spy", "--print"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=10, env=env)
    lines = result.stdout.strip().splitlines()
    check(result.returncode == 0 and len(lines) == 1,
          f"dream spy --print (live) exited {result.returncode} with {len(lines)} lines: {result.stdout.strip()}")
    _, url = parse_spy_line(lines[0])
    check(url.startswith(live_url), f"live spy should listen on $LCM_DEFAULT_URL {live_url}, got {url}")

    missing = ctx.path("no_such.lcmlog")
    code, text = ctx.run([args.dream, "spy", "--print", "--log", missing])
    check(code != 0 and missing in text, f"dream spy --log on a missing file: exit {code}, output {text.strip()!r}")

    # Without a display lcm-spy would fail with a Java stack trace: refused at once, saying what to do.
    headless = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    result = subprocess.run([args.dream, "spy", "--log", log], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=20, env=headless)
    check(result.returncode == 1 and "no display" in result.stdout and "--print" in result.stdout,
          f"dream spy without a display: exit {result.returncode} (expected 1), output {result.stdout.strip()!r}")

    xvfb = shutil.which("xvfb-run")
    if xvfb:
        require_private_netns()  # lcm-spy joins a udpm group
        spy_argv = ["java", "-cp", ":".join(classpath), "lcm.spy.Spy", "--lcm-url=" + url]
        spy = ctx.start("spy_under_xvfb", [xvfb, "-a"] + spy_argv, own_group=True)
        try:
            code = spy.wait(timeout=5)
        except subprocess.TimeoutExpired:
            code = None
        output = ctx.output("spy_under_xvfb")
        check(code is None or code == 0, f"lcm-spy under Xvfb exited {code}: {output.strip()[-300:]}")
        check("Exception" not in output, f"lcm-spy under Xvfb printed an exception: {output.strip()[-300:]}")
        print("lcm-spy ran 5 s under Xvfb")
    print("spy command line ok: " + lines[0])


if __name__ == "__main__":
    main(test)
