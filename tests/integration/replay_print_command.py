#!/usr/bin/python3
"""replay_print_command: `dream replay --print` names a java command that can really start LCM's log
player window on a run, as `dream spy --print` does for lcm-spy.

Checks the printed line of `dream replay --print RUN_FOLDER`: `java -Xmx64m -Xms32m -cp LCM_JAR
lcm.logging.LogPlayer --lcm-url URL LOG` (no -Xincgc, which Java 17 refuses; the URL as its own
word, since LogPlayer cuts `--lcm-url=URL` at every '='), LOG the folder's
run.lcmlog, URL $LCM_DEFAULT_URL; that the class is on that classpath (javap) and its own --help
answers; --paused and --lcm-url are passed on; --spy adds a `dream spy --lcm-url=URL` line on the
same URL; an .lcmlog path works as well as its folder; and a missing path, a folder without a log
and a file that is not an LCM log are refused with exit 1, naming the file. A GUI cannot run here:
only when xvfb-run exists is the printed player started under Xvfb for 5 s (private network
namespace), and it must not die with an exception.

Usage: netns.sh replay_print_command.py --dream BIN --source DIR
"""

import os
import shlex
import shutil
import subprocess

from dreamtest import argument_parser, check, main, require_private_netns


def printed(dream, argv, env):
    result = subprocess.run([dream, "replay", "--print"] + argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, timeout=10, env=env)
    check(result.returncode == 0, f"dream replay --print {argv} exited {result.returncode}: {result.stdout.strip()}")
    return [shlex.split(line) for line in result.stdout.strip().splitlines()]


def test(ctx):
    args = argument_parser().parse_args()
    run = ctx.path("run")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", run,
             "--steps", "5"], expect=0)
    log = os.path.join(run, "run.lcmlog")

    env = dict(os.environ)
    url = "udpm://239.255.76.67:7671?ttl=0"
    env["LCM_DEFAULT_URL"] = url
    lines = printed(args.dream, [run], env)
    check(len(lines) == 1, f"expected one command line, got {lines}")
    words = lines[0]
    check(words[:4] == ["java", "-Xmx64m", "-Xms32m", "-cp"] and words[5] == "lcm.logging.LogPlayer"
          and "-Xincgc" not in words,
          f"expected `java -Xmx64m -Xms32m -cp LCM_JAR lcm.logging.LogPlayer ...`, got {words}")
    jar = words[4]
    check(os.path.isfile(jar) and os.path.basename(jar) == "lcm.jar", f"classpath {jar} is not an existing lcm.jar")
    # dream adds its receive buffer size to a udpm URL (architecture.md, Transport).
    check(len(words) == 9 and words[6] == "--lcm-url" and words[7].startswith(url) and words[8] == log,
          f"expected --lcm-url {url}... {log}, got {words[6:]}")

    javap = shutil.which("javap")
    check(javap, "javap not found (apt-get install default-jdk-headless)")
    code, text = ctx.run([javap, "-cp", jar, "lcm.logging.LogPlayer"], timeout=60)
    check(code == 0 and "main(java.lang.String[])" in text, f"lcm.logging.LogPlayer not on {jar}: {text[-300:]}")
    code, text = ctx.run(["java", "-Djava.awt.headless=true", "-cp", jar, "lcm.logging.LogPlayer", "--help"],
                         timeout=60)
    check("--paused" in text and "--lcm-url" in text, f"LogPlayer --help does not list its options: {text[-300:]}")

    # The URL reaches the player whole: headless, LogPlayer parses its words and opens LCM (which
    # says what TTL it got) before it fails to open its window; a cut URL makes its parser complain.
    # (LCM's threads keep the JVM alive after that: close() ends its process group.)
    require_private_netns()  # the player joins a udpm group
    ctx.start("headless_player", words[:1] + ["-Djava.awt.headless=true"] + words[1:], own_group=True)
    ctx.wait_for_output("headless_player", "HeadlessException", timeout=60)
    text = ctx.output("headless_player")
    check("TTL set to zero" in text and "Invalid key-value pair" not in text,
          f"the log player did not get the whole URL {words[7]}: {text.strip()[-300:]}")
    # Its LCM threads keep it running and holding the player's UDP port: ended here, so the player
    # under Xvfb below can bind it ("BindException: Address already in use" otherwise).
    ctx.stop("headless_player")

    other = "udpm://239.255.76.67:7672?ttl=0"
    lines = printed(args.dream, [log, "--paused", "--spy", "--lcm-url", other], env)
    # In the order to start them: the spy first (it must subscribe before the player plays).
    check(len(lines) == 2, f"--spy: expected a spy and the player line, got {lines}")
    spy_line, player_line = lines
    player_url = player_line[7]
    check(player_line[6] == "--lcm-url" and player_url.startswith(other) and player_line[8:] == ["--paused", log],
          f"--paused/--lcm-url not passed on: {player_line}")
    check(spy_line[1:] == ["spy", "--lcm-url=" + player_url] and os.path.basename(spy_line[0]) == "dream",
          f"--spy: expected `dream spy --lcm-url={player_url}` first, got {spy_line}")

    code, text = ctx.run([args.dream, "replay", "--help"])
    check(code == 0 and "seek" in text and "--print-command" in text, f"dream replay --help: {code} {text[-400:]}")

    missing = ctx.path("no_such_run")
    empty_folder = ctx.path("empty_folder")
    os.makedirs(empty_folder)
    not_a_log = ctx.path("notes.lcmlog")
    with open(not_a_log, "w") as f:
        f.write("not an LCM log\n")
    for bad, named, words in [(missing, missing, "no such file or folder"),
                              (empty_folder, os.path.join(empty_folder, "run.lcmlog"), "is missing"),
                              (not_a_log, not_a_log, "not an LCM log")]:
        code, text = ctx.run([args.dream, "replay", "--print", bad])
        check(code == 1 and named in text and words in text,
              f"dream replay {bad}: exit {code} (expected 1), output {text.strip()!r}")

    # Without a display the JVM would print a HeadlessException and never exit: refused at once.
    headless = {k: v for k, v in env.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    result = subprocess.run([args.dream, "replay", run], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            timeout=20, env=headless)
    check(result.returncode == 1 and "no display" in result.stdout and "--print" in result.stdout,
          f"dream replay without a display: exit {result.returncode} (expected 1), output {result.stdout.strip()!r}")

    xvfb = shutil.which("xvfb-run")
    if xvfb:
        require_private_netns()  # the player publishes on a udpm group
        player = ctx.start("player_under_xvfb", [xvfb, "-a"] + printed(args.dream, [run], env)[0], own_group=True)
        try:
            code = player.wait(timeout=5)
        except subprocess.TimeoutExpired:
            code = None
        output = ctx.output("player_under_xvfb")
        check(code is None or code == 0, f"the log player under Xvfb exited {code}: {output.strip()[-300:]}")
        check("Exception" not in output, f"the log player under Xvfb printed an exception: {output.strip()[-300:]}")
        print("the log player ran 5 s under Xvfb")
    print("replay command line ok: " + " ".join(words))


if __name__ == "__main__":
    main(test)
