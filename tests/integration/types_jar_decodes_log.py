#!/usr/bin/python3
"""types_jar_decodes_log: the Java types jar (what lcm-spy loads) decodes every event of a run log.

Makes a run log (dream run), compiles tests/java/DecodeLog.java against lcm.jar and the types
jar, and runs it: every DREAM_* event must be identified by its fingerprint among the jar's
classes (as lcm-spy does), decode completely and re-encode to the same bytes, and the channels
must carry DREAM_POSES -> dream.robot_poses_t, DREAM_CMD_<n> -> dream.velocity_command_t,
DREAM_OBSTACLES -> dream.obstacles_t, DREAM_STATUS -> dream.run_status_t, DREAM_VERDICT ->
dream.run_verdict_t (once, the last event); and, on a run with
radios (hrvo_circle), DREAM_RADIO_<n> -> dream.radio_message_t.

Usage: types_jar_decodes_log.py --dream BIN --source DIR --types-jar JAR --lcm-jar JAR [--javac BIN --java BIN]
"""

import os
import shutil

from dreamtest import argument_parser, check, main, read_summary

EXPECTED = {
    "DREAM_POSES": "dream.robot_poses_t",
    "DREAM_CMD_[0-9]+": "dream.velocity_command_t",
    "DREAM_OBSTACLES": "dream.obstacles_t",
    "DREAM_STATUS": "dream.run_status_t",
    "DREAM_VERDICT": "dream.run_verdict_t",  # the log's last event: the one judge's verdict (issue 33)
}


def test(ctx):
    parser = argument_parser()
    parser.add_argument("--types-jar", required=True)
    parser.add_argument("--lcm-jar", required=True)
    parser.add_argument("--javac", default=shutil.which("javac"))
    parser.add_argument("--java", default=shutil.which("java"))
    args = parser.parse_args()
    for jar in (args.types_jar, args.lcm_jar):
        check(os.path.isfile(jar), f"{jar} is missing")
    javac, java = args.javac, args.java
    check(javac and java and os.path.exists(javac) and os.path.exists(java),
          "javac/java not found (apt-get install default-jdk-headless)")

    run = ctx.path("run")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", run],
            expect=0)
    classes = ctx.path("classes")
    os.mkdir(classes)
    classpath = ":".join([args.lcm_jar, args.types_jar])
    ctx.run([javac, "-Xlint:all", "-Werror", "-cp", classpath, "-d", classes,
             os.path.join(args.source, "tests", "java", "DecodeLog.java")], timeout=60, expect=0)
    log = os.path.join(run, "run.lcmlog")
    code, text = ctx.run([java, "-cp", classes + ":" + classpath, "DecodeLog", log, args.types_jar]
                         + [f"{regex}={name}" for regex, name in EXPECTED.items()], timeout=60)
    print(text.strip())
    last = text.strip().splitlines()[-1] if text.strip() else "(no output)"
    check(code == 0, f"DecodeLog: {last}")

    counts = {}
    for line in text.strip().splitlines()[:-1]:
        channel, type_name, count = line.split()
        counts[channel] = (type_name, int(count))
    summary = read_summary(run)
    check(sum(n for _, n in counts.values()) == summary["log_events"],
          f"DecodeLog decoded {sum(n for _, n in counts.values())} events, summary.json says {summary['log_events']}")
    check(counts.get("DREAM_POSES", (None, 0))[1] == summary["steps"] + 1,
          f"DREAM_POSES: {counts.get('DREAM_POSES')} events, expected steps + 1 = {summary['steps'] + 1}")
    check(counts.get("DREAM_VERDICT") == ("dream.run_verdict_t", 1),
          f"DREAM_VERDICT: {counts.get('DREAM_VERDICT')}, expected one dream.run_verdict_t")
    check(sorted(c for c in counts if c.startswith("DREAM_CMD_")) == [f"DREAM_CMD_{i}" for i in range(8)],
          f"expected DREAM_CMD_0..7, got {sorted(c for c in counts if c.startswith('DREAM_CMD_'))}")

    # An experiment with radios: DREAM_RADIO_<n> decodes as radio_message_t too.
    radio_run = ctx.path("radio_run")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "hrvo_circle.yaml"), "--out", radio_run,
             "--steps", "200", "--all-steps"], expect=0)
    expected = dict(EXPECTED, **{"DREAM_RADIO_[0-9]+": "dream.radio_message_t"})
    code, text = ctx.run([java, "-cp", classes + ":" + classpath, "DecodeLog", os.path.join(radio_run, "run.lcmlog"),
                          args.types_jar] + [f"{regex}={name}" for regex, name in expected.items()], timeout=60)
    last = text.strip().splitlines()[-1] if text.strip() else "(no output)"
    check(code == 0, f"DecodeLog on the radio run: {last}")
    radio = [line.split() for line in text.strip().splitlines()[:-1] if line.startswith("DREAM_RADIO_")]
    check(len(radio) == 10 and all(t == "dream.radio_message_t" for _, t, _ in radio),
          f"expected DREAM_RADIO_0..9 decoded as dream.radio_message_t, got {radio}")


if __name__ == "__main__":
    main(test)
