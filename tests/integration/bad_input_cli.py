#!/usr/bin/python3
"""bad_input_cli: every mistake a user can make on the command line or in a config is refused with
the documented exit code and a one-line message that names the file, line, key and value.

Each case runs `dream` on a broken input and checks: the exit code, that the output is exactly one
line starting with "dream" and holding every expected fragment, and that no output folder the
command was given (refused_out*) was created.

Usage: netns.sh bad_input_cli.py --dream BIN --source DIR
"""

import json
import os
import re
import shutil
import struct
import subprocess

from dreamtest import arguments, check, config_with, fail, main, read_events, require_private_netns

EXIT_INPUT = 1
EXIT_USAGE = 2
EXIT_NOT_COMPARED = 2  # dream log diff exits as diff(1): 2 when it could not compare


def mutate(source_config, path, old, new):
    """Writes source_config with the first line matching regex `old` replaced by `new`; returns
    (path, line number of the change)."""
    with open(source_config) as f:
        lines = f.read().split("\n")
    for number, line in enumerate(lines, start=1):
        if re.search(old, line):
            lines[number - 1] = re.sub(old, new, line)
            with open(path, "w") as f:
                f.write("\n".join(lines))
            return path, number
    fail(f"internal: no line of {source_config} matches {old!r}")


def truncated_log(ctx, dream, config):
    """A real run log cut in the middle of an event's data; returns (path, events before the cut)."""
    out = ctx.path("good_run")
    ctx.run([dream, "-q", "run", config, "--out", out], expect=0)
    log = os.path.join(out, "run.lcmlog")
    events = list(read_events(log))
    keep = len(events) // 2
    offset = sum(28 + len(e.channel) + len(e.data) for e in events[:keep])
    cut = offset + 28 + len(events[keep].channel) + len(events[keep].data) // 2
    with open(log, "rb") as f:
        data = f.read()
    check(0 < cut < len(data), "internal: cut point outside the log")
    path = ctx.path("truncated.lcmlog")
    with open(path, "wb") as f:
        f.write(data[:cut])
    return path, keep


def test(ctx):
    args = arguments()
    require_private_netns()  # `dream launch` of a broken config must not reach the network, but might
    dream = args.dream
    config = os.path.join(args.source, "config", "go_to_goal.yaml")

    def broken(name, old, new):
        return mutate(config, ctx.path(name + ".yaml"), old, new)

    robots51, robots51_line = broken("robots51", r"^robots: 8", "robots: 51")
    eight, eight_line = broken("eight", r"^robots: 8", "robots: eight")
    overlap, overlap_line = broken("overlap", r"\[0\.459, 0\.693, 2\.749\]", "[1.109, 0.287, 1.963]")
    outside, outside_line = broken("outside", r"\[0\.459, 0\.693, 2\.749\]", "[1.9, 0.693, 2.749]")
    inside, inside_line = broken("inside", r"\[0\.459, 0\.693, 2\.749\]", "[0.0, 0.0, 2.749]")  # the centre block
    kind, kind_line = broken("kind", r"kind: go_to_goal", "kind: go_to_gaol")
    # The same mistake for `dream launch`, with a short start timeout: if launch does not check the
    # controller section itself, its agents fail and the simulator waits start_timeout_s in vain.
    launch_kind = config_with(kind, ctx.path("launch_kind.yaml"), start_timeout_s=3)
    typo, typo_line = broken("typo", r"^stop_when_done:", "stop_when_dnoe:")
    mode, mode_line = broken("mode", r"mode: lockstep", "mode: fast")
    timeout, timeout_line = broken("timeout", r"agent_timeout_s: 2\.0", "agent_timeout_s: -1")
    goals, _ = broken("goals", r"- \[0\.416, -0\.134\]", "")
    bad_yaml, _ = broken("bad_yaml", r"^robots: 8", "robots: [8")
    # yaml-cpp keeps the first of two equal keys and reads only the first document, without a word.
    duplicate, first_gain_line = broken("duplicate", r"^  gain: 0\.8.*", "  gain: 0.8\n  gain: 0.5")
    second_doc = ctx.path("second_doc.yaml")
    with open(config) as f:
        config_text = f.read()
    with open(second_doc, "w") as f:
        f.write(config_text + "---\n" + config_text.replace("robots: 8", "robots: 4"))
    second_doc_line = config_text.count("\n") + 1
    wall, wall_line = broken("wall", r"\[1\.109, 0\.287, 1\.963\]", "[1.6, 0.287, 1.963]")  # on the wall
    missing = ctx.path("no_such_config.yaml")
    not_log = ctx.path("not_a_log.lcmlog")
    with open(not_log, "w") as f:
        f.write("name: this is text, not an LCM log\n")
    truncated, kept_events = truncated_log(ctx, dream, config)
    good_run = ctx.path("good_run")
    no_parent = ctx.path("no", "such", "folder")
    empty_log = ctx.path("empty.lcmlog")
    open(empty_log, "wb").close()
    # A run folder whose log holds no poses: only the DREAM_STATUS events of a real run.
    no_poses_run = ctx.path("no_poses_run")
    os.mkdir(no_poses_run)
    with open(config) as f, open(os.path.join(no_poses_run, "config.yaml"), "w") as out:
        out.write(f.read())
    with open(os.path.join(no_poses_run, "run.lcmlog"), "wb") as out:
        for event in read_events(os.path.join(good_run, "run.lcmlog")):
            if event.channel == "DREAM_STATUS":
                channel = event.channel.encode()
                out.write(b"".join([(0xEDA1DA01).to_bytes(4, "big"), event.eventnum.to_bytes(8, "big"),
                                    event.utime.to_bytes(8, "big"), len(channel).to_bytes(4, "big"),
                                    len(event.data).to_bytes(4, "big"), channel, event.data]))
    folder_without_log = ctx.path("folder_without_log")
    os.mkdir(folder_without_log)
    # A run folder whose log gives robot 0 an infinite x at step 3 (compare printed "inf" distances).
    inf_run = ctx.path("inf_run")
    os.mkdir(inf_run)
    shutil.copyfile(os.path.join(good_run, "config.yaml"), os.path.join(inf_run, "config.yaml"))
    inf_log = os.path.join(inf_run, "run.lcmlog")
    with open(inf_log, "wb") as out:
        for event in read_events(os.path.join(good_run, "run.lcmlog")):
            data = event.data
            # robot_poses_t: fingerprint, utime, step (at byte 16), run_id, num_robots, then x[0] at byte 36.
            if event.channel == "DREAM_POSES" and int.from_bytes(data[16:24], "big") == 3:
                data = data[:36] + struct.pack(">d", float("inf")) + data[44:]
            channel = event.channel.encode()
            out.write(b"".join([(0xEDA1DA01).to_bytes(4, "big"), event.eventnum.to_bytes(8, "big"),
                                event.utime.to_bytes(8, "big"), len(channel).to_bytes(4, "big"),
                                len(data).to_bytes(4, "big"), channel, data]))
    # A config path that is no file: a FIFO (its open waited for a writer forever, deaf to Ctrl-C)
    # and /dev/zero (read 2 GB, then bad_alloc).
    fifo = ctx.path("fifo.yaml")
    os.mkfifo(fifo)
    # --set values with the aliases a config file may not hold: one that contains itself (copying it
    # overflowed the stack: SIGSEGV) and ten levels of ten (36 s and 3.9 GB, then bad_alloc).
    self_alias = "controller.gain=&a [*a]"
    laughs = "&a0 [x,x,x,x,x,x,x,x,x,x]"
    for level in range(1, 10):
        laughs += f", &a{level} [" + ",".join([f"*a{level - 1}"] * 10) + "]"
    billion_laughs = f"controller.gain=[{laughs}]"
    # The folder of a run killed by SIGKILL: only its run.lcmlog.part (a rerun used to truncate it).
    killed_run = ctx.path("killed_run")
    os.mkdir(killed_run)
    killed_part = os.path.join(killed_run, "run.lcmlog.part")
    shutil.copyfile(truncated, killed_part)
    with open(killed_part, "rb") as f:
        killed_bytes = f.read()

    def where(path, line):
        return f"{path}:{line}:"

    # (name, argv, expected exit code, fragments the output line must hold, is a config error)
    cases = [
        ("unknown subcommand", ["frobnicate"], EXIT_USAGE, ["'frobnicate'", "dream --help"], False),
        ("unknown subcommand after a global option", ["-q", "sewp"], EXIT_USAGE, ["'sewp'", "known: run"], False),
        ("unknown option", ["run", config, "--speed", "3"], EXIT_USAGE, ["--speed", "dream run --help"], False),
        # A near miss is answered with the word meant.
        ("near-miss subcommand", ["rnu", config], EXIT_USAGE, ["'rnu' (did you mean 'run'?)", "known: run"], False),
        ("near-miss option", ["run", config, "--ovewrite"], EXIT_USAGE,
         ["--ovewrite (did you mean '--overwrite'?)", "dream run --help"], False),
        ("near-miss command of a group", ["log", "ifno", truncated], EXIT_USAGE,
         ["(did you mean 'info'?)", "dream log --help"], False),
        ("unknown global option", ["--bogus", "run", config], EXIT_USAGE, ["'--bogus'", "dream --help"], False),
        ("missing argument", ["run"], EXIT_USAGE, ["config", "required", "dream run --help"], False),
        ("arguments to a script", ["run", "s.py", "3"], EXIT_USAGE,
         ["not expected: 3", "a Robotarium script (s.py) takes no arguments of its own", "dream run --help"], False),
        ("log without its subcommand", ["log"], EXIT_USAGE, ["subcommand", "dream log --help"], False),
        ("unknown option of a nested command", ["log", "info", truncated, "--all"], EXIT_USAGE,
         ["--all", "dream log info --help"], False),
        ("--steps 0", ["run", config, "--steps", "0", "--out", ctx.path("refused_out_steps0")], EXIT_USAGE,
         ["--steps", "whole number", "got 0"], False),
        ("lab-replay --steps 2.5", ["lab-replay", good_run, "--steps", "2.5", "--out", ctx.path("refused_out_r")],
         EXIT_USAGE, ["--steps", "whole number", "got 2.5"], False),
        ("agent --idle-timeout -1", ["agent", config, "--idle-timeout", "-1"], EXIT_USAGE,
         ["--idle-timeout", "seconds > 0", "got -1"], False),
        ("render --trail nan", ["render", good_run, "--trail", "nan", "--out", ctx.path("refused_out_t.png")],
         EXIT_USAGE, ["--trail", "seconds >= 0", "got nan"], False),
        ("missing config file", ["run", missing, "--out", ctx.path("refused_out1")], None, [missing], False),
        ("robots: 51", ["run", robots51, "--out", ctx.path("refused_out2")], EXIT_INPUT,
         [where(robots51, robots51_line), "robots", "51", "50", "add `sim_only: true` to run up to 128 robots"], True),
        ("robots: eight", ["run", eight, "--out", ctx.path("refused_out3")], EXIT_INPUT,
         [where(eight, eight_line), "robots", "'eight'"], True),
        ("overlapping initial poses", ["run", overlap, "--out", ctx.path("refused_out4")], EXIT_INPUT,
         [where(overlap, overlap_line), "initial_poses[1]", "robots 0 and 1", "collision"], True),
        ("pose outside the arena", ["run", outside, "--out", ctx.path("refused_out5")], EXIT_INPUT,
         [where(outside, outside_line), "initial_poses[1]", "1.900", "outside the arena"], True),
        ("pose inside an obstacle", ["run", inside, "--out", ctx.path("refused_out_inside")], EXIT_INPUT,
         [where(inside, inside_line), "initial_poses[1]", "robot 1 starts inside obstacle 0", "(0.000, 0.000, 2.749)"],
         True),
        ("unknown controller kind", ["run", kind, "--out", ctx.path("refused_out6")], EXIT_INPUT,
         [where(kind, kind_line), "controller.kind", "'go_to_gaol'", "go_to_goal"], True),
        ("top-level key typo", ["run", typo, "--out", ctx.path("refused_out7")], EXIT_INPUT,
         [where(typo, typo_line), "stop_when_dnoe", "unknown key", "stop_when_done"], True),
        ("unknown world mode", ["run", mode, "--out", ctx.path("refused_out8")], EXIT_INPUT,
         [where(mode, mode_line), "world.mode", "'fast'", "lockstep"], True),
        ("negative agent timeout", ["run", timeout, "--out", ctx.path("refused_out9")], EXIT_INPUT,
         [timeout + ":", "agent_timeout_s", "-1"], True),
        ("too few goals", ["run", goals, "--out", ctx.path("refused_out10")], EXIT_INPUT,
         [goals + ":", "controller.goals", "(8)", "got 7"], True),
        ("invalid YAML", ["run", bad_yaml, "--out", ctx.path("refused_out11")], EXIT_INPUT,
         [bad_yaml + ":", "not valid YAML"], True),
        ("duplicate key", ["run", duplicate, "--out", ctx.path("refused_out_duplicate")], EXIT_INPUT,
         [where(duplicate, first_gain_line + 1), "controller.gain", "duplicate key",
          f"first given at line {first_gain_line}"], True),
        ("second YAML document", ["run", second_doc, "--out", ctx.path("refused_out_second_doc")], EXIT_INPUT,
         [where(second_doc, second_doc_line), "a second YAML document (---) is not read"], True),
        ("start pose on the wall", ["run", wall, "--out", ctx.path("refused_out_wall")], EXIT_INPUT,
         [where(wall, wall_line), "initial_poses[0]", "closer than its radius 0.055 m", "start_inside_arena"], True),
        ("launch with an unknown controller kind", ["launch", launch_kind, "--out", ctx.path("refused_out_launch")],
         EXIT_INPUT, [launch_kind + ":", "controller.kind", "'go_to_gaol'"], True),
        ("agent config error", ["agent", robots51], EXIT_INPUT, [where(robots51, robots51_line), "robots"], True),
        ("--out under a missing folder", ["run", config, "--out", no_parent], EXIT_INPUT,
         [no_parent, "does not exist"], False),
        ("--robots out of range", ["agent", config, "--robots", "9"], EXIT_INPUT, ["--robots", "'9'", "0..7"], False),
        ("--robots backwards range", ["agent", config, "--robots", "5-2"], EXIT_INPUT, ["--robots", "5-2"], False),
        ("--lcm-url without provider", ["run", config, "--lcm-url", "bogus", "--out", ctx.path("refused_out12")], EXIT_INPUT,
         ["'bogus'", "memq://"], False),
        ("log info on a text file", ["log", "info", not_log], EXIT_INPUT, [not_log, "not an LCM log"], False),
        ("log info on a truncated log", ["log", "info", truncated], EXIT_INPUT,
         [truncated, "cut short", f"after event {kept_events}"], False),
        ("log diff with a truncated log", ["log", "diff", truncated, truncated], EXIT_NOT_COMPARED,
         [truncated, "cut short"], False),
        ("log diff --channels not a regex", ["log", "diff", truncated, truncated, "--channels", "("], EXIT_NOT_COMPARED,
         ["--channels '(' is not a regular expression"], False),
        ("log info on an empty log", ["log", "info", empty_log], EXIT_INPUT, [empty_log, "empty log"], False),
        ("log info on a folder without a log", ["log", "info", folder_without_log], EXIT_INPUT,
         [os.path.join(folder_without_log, "run.lcmlog"), "no such log file"], False),
        ("export of a run with no poses", ["export", no_poses_run, "--out", ctx.path("refused_out_export")],
         EXIT_INPUT, [no_poses_run, "no DREAM_POSES"], False),
        ("export --out under a missing folder", ["export", good_run, "--out", ctx.path("refused_out_e", "x")],
         EXIT_INPUT, [ctx.path("refused_out_e"), "does not exist"], False),
        ("compare with a run with no poses", ["compare", good_run, no_poses_run, "--out", ctx.path("refused_out_c")],
         EXIT_INPUT, [no_poses_run, "no DREAM_POSES"], False),
        ("compare --out under a missing folder", ["compare", good_run, good_run, "--out", ctx.path("refused_out_c2", "x")],
         EXIT_INPUT, [ctx.path("refused_out_c2"), "does not exist"], False),
        ("lab-replay of a run with no poses", ["lab-replay", no_poses_run, "--out", ctx.path("refused_out_l")],
         EXIT_INPUT, [no_poses_run, "no DREAM_POSES"], False),
        ("lab-replay --out under a missing folder", ["lab-replay", good_run, "--out", ctx.path("refused_out_l2", "x")],
         EXIT_INPUT, [ctx.path("refused_out_l2"), "does not exist"], False),
        ("import of a missing result", ["import", ctx.path("no_result.npy"), "--export", good_run, "--out",
         ctx.path("refused_out_i")], EXIT_INPUT, [good_run], False),
        ("compare with a pose that is not finite", ["compare", good_run, inf_run, "--out", ctx.path("refused_out_inf")],
         EXIT_INPUT, [inf_log + ": robot 0's pose at step 3 is not finite (x inf"], False),
        # Export named no file here ("ViolationChecker::Check: step 3: robot 0 has a pose that is not finite").
        ("export of a run with a pose that is not finite", ["export", inf_run, "--out", ctx.path("refused_out_inf_e")],
         EXIT_INPUT, [inf_log + ": robot 0's pose at step 3 is not finite (x inf"], False),
        ("run of a FIFO", ["run", fifo, "--out", ctx.path("refused_out_fifo")], EXIT_INPUT,
         [fifo, "is a FIFO (named pipe), not a config file"], False),
        ("sweep of a FIFO", ["sweep", fifo, "--out", ctx.path("refused_out_fifo_sweep")], EXIT_INPUT,
         [fifo, "is a FIFO (named pipe), not a config file"], False),
        ("run of /dev/zero", ["run", "/dev/zero", "--out", ctx.path("refused_out_zero")], EXIT_INPUT,
         ["/dev/zero: is a character device, not a config file"], False),
        ("run of /dev/urandom", ["run", "/dev/urandom", "--out", ctx.path("refused_out_urandom")], EXIT_INPUT,
         ["/dev/urandom: is a character device, not a config file"], False),
    ] + [
        (f"{command} --set with an alias to itself", [command, config, "--set", self_alias] + out, EXIT_INPUT,
         ["--set controller.gain:1: [0]: contains itself through an alias (*)"], False)
        for command, out in (("run", ["--out", ctx.path("refused_out_alias_run")]),
                             ("sim", ["--out", ctx.path("refused_out_alias_sim")]),
                             ("launch", ["--out", ctx.path("refused_out_alias_launch")]),
                             ("agent", []),
                             ("sweep", ["--out", ctx.path("refused_out_alias_sweep")]))
    ] + [
        (f"{command} --set with a billion laughs", [command, config, "--set", billion_laughs] + out, EXIT_INPUT,
         ["--set controller.gain:1: ", "aliases (*) expand this value to more than 1000000 values"], False)
        for command, out in (("run", ["--out", ctx.path("refused_out_laughs_run")]),
                             ("sweep", ["--out", ctx.path("refused_out_laughs_sweep")]))
    ] + [
        (f"{command} {option} without '='", [command, config, option, "radius_m"] + out, EXIT_USAGE,
         [f"{option}: expected KEY=VALUE", "got radius_m", f"dream {command} --help"], False)
        for command, option, out in (("run", "--set", ["--out", ctx.path("refused_out_kv_run")]),
                                     ("launch", "--set", ["--out", ctx.path("refused_out_kv_launch")]),
                                     ("sweep", "--set", ["--out", ctx.path("refused_out_kv_sweep")]),
                                     ("sweep", "--zip", ["--out", ctx.path("refused_out_kv_zip")]))
    ] + [
        ("run into the folder of a killed run", ["run", config, "--out", killed_run], EXIT_INPUT,
         [f"--out {killed_run} holds {killed_part} ({len(killed_bytes)} bytes), the log of a run that did not end",
          "move it out of the folder", "--overwrite deletes it"], False),
    ]

    problems = []
    for name, argv, expected_code, fragments, config_error in cases:
        code, text = ctx.run([dream] + argv, timeout=20)
        lines = [line for line in text.strip().splitlines() if line.strip()]
        first = lines[0] if lines else ""
        if expected_code is None:
            if code in (0, 130) or code >= 128:
                problems.append(f"{name}: exit {code}, expected a non-zero input/usage error")
        elif code != expected_code:
            problems.append(f"{name}: exit {code}, expected {expected_code} ({first!r})")
        if code >= 128:
            problems.append(f"{name}: dream died from signal {code - 128}")
        missing_fragments = [f for f in fragments if f not in first]
        if missing_fragments:
            problems.append(f"{name}: message {first!r} lacks {missing_fragments}")
        if len(lines) != 1:
            problems.append(f"{name}: expected a one-line error, got {len(lines)} lines: {lines[:3]}")
        elif not first.startswith("dream"):
            problems.append(f"{name}: the message does not start with 'dream': {first!r}")
        if not lines:
            problems.append(f"{name}: no message at all")
        # An --out given as refused_out*[/...] must not exist afterwards, nor any folder above it.
        refused_roots = [os.path.join(ctx.dir, os.path.relpath(a, ctx.dir).split(os.sep)[0])
                         for a in argv if a.startswith(ctx.path("refused_out"))]
        if any(os.path.exists(root) for root in refused_roots):
            problems.append(f"{name}: the refused command created its output folder")
        print(f"{name}: exit {code}: {first}")

    # The killed run's log is as it was; --overwrite replaces it, as it replaces a finished run.
    with open(killed_part, "rb") as f:
        if f.read() != killed_bytes:
            problems.append("run into the folder of a killed run: its run.lcmlog.part was changed")
    code, text = ctx.run([dream, "-q", "run", config, "--out", killed_run, "--overwrite", "--steps", "5"], timeout=60)
    if code != 0 or os.path.exists(killed_part) or not os.path.exists(os.path.join(killed_run, "run.lcmlog")):
        problems.append(f"run --overwrite into the folder of a killed run: exit {code}, .part left: "
                        f"{os.path.exists(killed_part)}: {text.strip()[-300:]}")

    # A folder name that is not UTF-8 (Latin-1 "r\xe9un") is no reason to lose an output:
    # comparison.json holds U+FFFD for the byte, the picture a '?'.
    latin1_run = os.fsdecode(os.fsencode(ctx.path("good_run")) + b"_r\xe9un")
    shutil.copytree(good_run, latin1_run)
    compare_out = ctx.path("latin1_compare")
    # dream prints the path as given (bytes), so the output is not read as UTF-8 here.
    done = subprocess.run([dream, "compare", good_run, latin1_run, "--out", compare_out],
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=60)
    code = done.returncode
    if code != 0:
        problems.append(f"compare with a Latin-1 folder name: exit {code}: {done.stdout[-300:]!r}")
    else:
        with open(os.path.join(compare_out, "comparison.json"), encoding="utf-8") as f:
            folders = [run["folder"] for run in json.load(f).values() if isinstance(run, dict) and "folder" in run]
        if not any("\ufffd" in folder for folder in folders):
            problems.append(f"compare with a Latin-1 folder name: comparison.json folders {folders!r}")
        if not os.path.exists(os.path.join(compare_out, "comparison.png")):
            problems.append("compare with a Latin-1 folder name: no comparison.png")
    check(not problems, "; ".join(problems))


if __name__ == "__main__":
    main(test)
