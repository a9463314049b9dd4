#!/usr/bin/python3
"""The Robotarium bridge end to end through the `dream` command.

    bridge_roundtrip.py --dream build/dream --source . --simulator standin|official

For go_to_goal and each thesis experiment whose config exists (hrvo_circle,
line_deployment, voronoi_coverage, affine_formation): dream run, dream export
(track), dream check-submission in the chosen Robotarium simulator, which runs
the exported script, imports what it saved and compares it with the run. Each
must run without errors or warnings, and track the plan with an RMS error
under 2 cm. Then, once: the replay strategy, dream compare, dream lab-replay
(the agents against the lab's poses), lcm-logplayer on an imported log, and
bad input through the command line (too many robots, over the duration cap,
code in a config string, NaN in a result, an output path leading outside).

With --simulator official the checkout comes from $ROBOTARIUM_PYTHON_SIMULATOR
(a checkout, or a bare git repository of robotarium_python_simulator); without
it the test prints SKIP and exits 77. It also runs one export in the official
simulator and in the stand-in from the same start and compares every pose.
"""

import argparse
import json
import os
import struct
import subprocess
import sys
import tempfile
import time

from bridge_driver import Failure, Skipped, check, drive, simulator_flags

EXPERIMENTS = ["go_to_goal", "hrvo_circle", "line_deployment", "voronoi_coverage", "affine_formation"]
RMS_LIMIT_M = 0.02


def run_with_code(argv, expect=0, cwd=None, timeout=600, env=None):
    started = time.monotonic()
    result = subprocess.run([str(a) for a in argv], capture_output=True, text=True, cwd=cwd, timeout=timeout,
                            env=env)
    output = result.stdout + result.stderr
    if expect is not None and result.returncode != expect:
        raise Failure("%s exited %d (expected %d):\n%s" % (" ".join(map(str, argv)), result.returncode, expect,
                                                          output[-3000:]))
    return result.returncode, output, time.monotonic() - started


def run(argv, expect=0, cwd=None, timeout=600, env=None):
    _, output, seconds = run_with_code(argv, expect, cwd, timeout, env)
    return output, seconds


def run_check(argv):
    """A go_to_goal check-submission in the stand-in: exit 0, or 5 when the lab run missed the goal by
    the official start-up drive's millimetres (docs/robotarium.md#measured); these calls check what
    is written, not the verdict."""
    code, output, seconds = run_with_code(argv, expect=None)
    if code not in (0, 5):
        raise Failure("%s exited %d (expected 0 or 5):\n%s" % (" ".join(map(str, argv)), code, output[-3000:]))
    return output, seconds


class Loop:
    def __init__(self, args, tmp, simulator_flags):
        self.dream = args.dream
        self.source = args.source
        self.tmp = tmp
        self.flags = simulator_flags
        self.report = []

    def path(self, *parts):
        return os.path.join(self.tmp, *parts)

    def experiment(self, name, strategy="track", barriers=False):
        config = os.path.join(self.source, "config", name + ".yaml")
        variant = strategy + ("_barriers" if barriers else "")
        sim_dir, export_dir, check_dir = (self.path(name + suffix) for suffix in ("_sim", "_export_" + variant,
                                                                                   "_check_" + variant))
        if not os.path.exists(os.path.join(sim_dir, "run.lcmlog")):
            _, seconds = run([self.dream, "run", config, "--out", sim_dir, "-q"])
            self.report.append("%s: dream run %.1f s" % (name, seconds))
        exported, _ = run([self.dream, "export", sim_dir, "--out", export_dir, "--strategy", strategy, "-q"] +
                          (["--barriers"] if barriers else []))
        check(os.path.isfile(os.path.join(export_dir, "UPLOAD.txt")), name + ": no UPLOAD.txt")
        flags = list(self.flags)
        note = ""
        if "start poses are crowded" in exported and "--require-official" in flags:
            # The official start-up drive deadlocks on crowded start poses (docs/robotarium.md):
            # check the script itself from its exact start poses.
            flags.append("--skip-initialization")
            note = ", start-up drive skipped (crowded start poses)"
        code, output, seconds = run_with_code([self.dream, "check-submission", export_dir, "--out", check_dir] + flags,
                                              expect=None)
        with open(os.path.join(check_dir, "check.json")) as f:
            result = json.load(f)
        where = "%s (%s, %s)" % (name, variant, result["simulator"])
        check(result["script_ok"], where + ": the script failed")
        check(result["debug_verdict"] == "clean",
              where + ": debug() verdict " + result["debug_verdict"] + ":\n" + result["debug_text"])
        verdict = one_judge_of(self, where, check_dir, export_dir, output)
        check(code == EXIT_OF_VERDICT[verdict], where + ": check-submission exited %d for a %s run" % (code, verdict))
        check(not result["python_warnings"], where + ": Python warnings: %s" % result["python_warnings"])
        check(result["complete"], where + ": the run did not complete")
        check("tracking_rms_m" in result, where + ": not compared with the run:\n" + output[-2000:])
        if strategy == "track":
            check(result["tracking_rms_m"] < RMS_LIMIT_M,
                  where + ": tracking RMS %.4f m >= %.2f m" % (result["tracking_rms_m"], RMS_LIMIT_M))
        self.report.append("%s: check-submission %.1f s, settle %d steps, tracking RMS %.2f cm, max %.2f cm%s" %
                           (where, seconds, result["settle_steps"], 100 * result["tracking_rms_m"],
                            100 * result["tracking_max_m"], note))
        return sim_dir, export_dir, check_dir


EXIT_OF_VERDICT = {"clean": 0, "warning": 0, "not_ready": 5, "rejected": 3}


def one_judge_of(loop, where, check_dir, export_dir, output):
    """Issue 33, one judge: check-submission's exit code and check.json verdict are the imported run's
    summary.json verdict, and `dream import` of the same result says the same."""
    with open(os.path.join(check_dir, "check.json")) as f:
        verdict = json.load(f)["verdict"]
    with open(os.path.join(check_dir, "summary.json")) as f:
        summary = json.load(f)
    check(verdict == summary["verdict"], where + ": check.json verdict %s, its summary.json %s" %
          (verdict, summary["verdict"]))
    check(verdict in ("clean", "warning", "not_ready"), where + ": verdict " + verdict + ":\n" + output[-2000:])
    check("\ngoal: " in output, where + ": check-submission did not print the goal:\n" + output[-1500:])
    result_file = os.path.join(check_dir, "lab_files", "dream_result.npy")
    imported = os.path.join(tempfile.mkdtemp(prefix="one_judge_", dir=loop.tmp), "lab")  # removed with it
    import_output, _ = run([loop.dream, "import", result_file, "--export", export_dir, "--out", imported, "-q"],
                           expect=EXIT_OF_VERDICT[verdict])
    with open(os.path.join(imported, "summary.json")) as f:
        check(json.load(f)["verdict"] == verdict, where + ": dream import of the same result judges otherwise")
    return verdict


def bad_input(loop):
    dream = loop.dream
    source = loop.source
    base = open(os.path.join(source, "config", "go_to_goal.yaml")).read()

    # 21 robots: refused, naming the rule and the fix; nothing written.
    goals = "\n".join("    - [%.2f, %.2f]" % (-1.2 + 0.3 * (i % 7), -0.6 + 0.5 * (i // 7)) for i in range(21))
    many = base.replace("robots: 8", "robots: 21")
    many = many[:many.index("initial_poses:")] + "initial_poses: {generate: {min_spacing_m: 0.3}}\n" + \
        many[many.index("controller:"):]
    many = many[:many.index("  goals:")] + "  goals:\n" + goals + "\n"
    many_config = loop.path("many.yaml")
    with open(many_config, "w") as f:
        f.write(many)
    run([dream, "run", many_config, "--out", loop.path("many_sim"), "--steps", "5", "-q"])
    output, _ = run([dream, "export", loop.path("many_sim"), "--out", loop.path("many_export")], expect=3)
    check("robots: the run has 21 robots; the Robotarium runs 1 to 20" in output, "21 robots: " + output)
    check("Fix: set `robots:` to at most 20" in output, "21 robots, no fix: " + output)
    check(not os.path.exists(loop.path("many_export")), "a refused export wrote files")

    # Over the duration cap.
    # The run's own verdict says so already (exit 3, rule lab_duration_cap), with the export's settle steps.
    output, _ = run([dream, "run", os.path.join(source, "config", "go_to_goal.yaml"), "--out", loop.path("long_sim"),
                     "--steps", "27100", "--all-steps", "-q"], expect=3)
    check("lab_duration_cap: the experiment takes 902.22 s with the export's settle steps, over the lab's cap of "
          "900.00 s" in output, "long run: " + output)
    output, _ = run([dream, "export", loop.path("long_sim"), "--out", loop.path("long_export")], expect=3)
    check("duration: 27100 steps + 240 settle steps take 902.2 s on the lab, over its cap of 900 s" in output,
          "duration: " + output)

    # Code in a config string: the script stays the template, nothing runs.
    marker = loop.path("PWNED")
    payload = "x'''\\\"\\\"\\\"\\n__import__('os').system('touch %s') # {0} %%s ${HOME}" % marker
    hostile = base.replace("description: eight robots drive from a wide ellipse to a small one",
                           'description: "%s"' % payload)
    check(hostile != base, "the injection test did not change the config")
    hostile_config = loop.path("hostile.yaml")
    with open(hostile_config, "w") as f:
        f.write(hostile)
    run([dream, "run", hostile_config, "--out", loop.path("hostile_sim"), "-q"])
    run([dream, "export", loop.path("hostile_sim"), "--out", loop.path("hostile_export"), "-q"])
    script = open(loop.path("hostile_export", "upload", "dream_main.py")).read()
    template = open(os.path.join(source, "bridge", "python", "dream_main.py")).read()
    check(script == template, "the exported script differs from the fixed template")
    run_check([dream, "check-submission", loop.path("hostile_export"), "--out", loop.path("hostile_check"),
               "--standin", "-q"])
    check(not os.path.exists(marker), "code from the config ran: %s exists" % marker)

    # A result with NaN: refused naming the file, nothing written.
    import numpy as np
    result = np.load(loop.path("go_to_goal_check_track", "lab_files", "dream_result.npy"))
    result[5, 4] = np.nan
    bad = loop.path("nan_result.npy")
    np.save(bad, result)
    output, _ = run([dream, "import", bad, "--export", loop.path("go_to_goal_export_track"), "--out",
                     loop.path("nan_lab")], expect=1)
    check(bad + ": row 5: x of robot 1 is nan" in output, "NaN: " + output)
    check(not os.path.exists(loop.path("nan_lab")), "a refused import wrote files")
    np.save(bad, result[:, :-5])  # a 7-robot result
    output, _ = run([dream, "import", bad, "--export", loop.path("go_to_goal_export_track"), "--out",
                     loop.path("nan_lab")], expect=1)
    check("as a result of a 7-robot run; this export has 8 robots" in output, "7 robots: " + output)

    # The lab verifier's rules against what was declared on the lab's form (UPLOAD.txt's by default).
    good = loop.path("go_to_goal_check_track", "lab_files", "dream_result.npy")
    export = loop.path("go_to_goal_export_track")
    # Declared as UPLOAD.txt says: not rejected (clean, or not_ready when the goal was missed by the
    # official start-up drive's millimetres, which the stand-in now reproduces).
    output, _ = run_check([dream, "import", good, "--export", export, "--out", loop.path("declared_lab")])
    check("verdict: clean" in output or "verdict: not_ready" in output, "declared as UPLOAD.txt says: " + output)
    output, _ = run([dream, "import", good, "--export", export, "--out", loop.path("declared_short_lab"),
                     "--declared-duration", "2"], expect=3)
    check("verifier_duration: " in output and "over 1.5 x the declared 2.00 s" in output, "too long: " + output)
    with open(loop.path("declared_short_lab", "summary.json")) as f:
        summary = json.load(f)
    check(summary["verdict"] == "rejected" and summary["lab"]["declared_duration_s"] == 2.0,
          "too long: summary.json %s, %s" % (summary["verdict"], summary["lab"]))
    output, _ = run([dream, "import", good, "--export", export, "--out", loop.path("declared_robots_lab"),
                     "--declared-robots", "9"], expect=3)
    check("verifier_robot_count: the script asks for 8 robots but 9 are declared" in output, "robots: " + output)

    # An output folder whose upload/ leads outside it.
    os.makedirs(loop.path("escape", "out"))
    os.makedirs(loop.path("escape", "elsewhere"))
    os.symlink(loop.path("escape", "elsewhere"), loop.path("escape", "out", "upload"))
    output, _ = run([dream, "export", loop.path("go_to_goal_sim"), "--out", loop.path("escape", "out")], expect=1)
    check("outside the output folder" in output, "escape: " + output)
    check(not os.listdir(loop.path("escape", "elsewhere")), "files were written outside the output folder")
    # Output folders: a check never replaces the run it compares with, nor another run unless
    # --overwrite; an export never writes into a run's folder.
    sim_dir = loop.path("go_to_goal_sim")
    with open(os.path.join(sim_dir, "run.lcmlog"), "rb") as f:
        simulated_log = f.read()
    output, _ = run([dream, "check-submission", export, "--standin", "--out", sim_dir], expect=1)
    check("is the simulated run the check compares with" in output, "check into its own run: " + output)
    output, _ = run([dream, "check-submission", export, "--standin", "--out", loop.path("hostile_check")], expect=1)
    check("already holds a run" in output and "--overwrite" in output, "check into a run: " + output)
    run_check([dream, "check-submission", export, "--standin", "--out", loop.path("hostile_check"), "--overwrite",
               "-q"])
    with open(loop.path("hostile_check", "check.json")) as f:
        check(json.load(f)["compared_with"] == sim_dir, "check --overwrite did not check the new export")
    output, _ = run([dream, "export", sim_dir, "--out", loop.path("hostile_sim")], expect=1)
    check("holds a run (run.lcmlog)" in output, "export into a run: " + output)
    output, _ = run([dream, "export", sim_dir, "--config", loop.path("absent.yaml"), "--out",
                     loop.path("absent_export")], expect=1)
    check("--config %s: no such file" % loop.path("absent.yaml") in output, "export --config absent: " + output)
    output, _ = run([dream, "check-submission", export, "--simulator", loop.path("absent"), "--out",
                     loop.path("absent_check")], expect=1)
    check("--simulator %s: no such folder" % loop.path("absent") in output, "check --simulator absent: " + output)
    # A folder that is no simulator checkout is named before anything is made (it exited 4 after).
    not_simulator = loop.path("not_a_simulator")
    os.makedirs(not_simulator, exist_ok=True)
    output, _ = run([dream, "check-submission", export, "--simulator", not_simulator, "--out",
                     loop.path("wrong_simulator_check")], expect=1)
    check("--simulator %s: has no rps/robotarium.py" % not_simulator in output
          and not os.path.exists(loop.path("wrong_simulator_check")),
          "check --simulator with a folder that is no checkout: " + output)
    output, _ = run([dream, "check-submission", export, "--out", loop.path("wrong_simulator_check")], expect=1,
                    env=dict(os.environ, ROBOTARIUM_PYTHON_SIMULATOR=not_simulator))
    check("$ROBOTARIUM_PYTHON_SIMULATOR %s: has no rps/robotarium.py" % not_simulator in output
          and not os.path.exists(loop.path("wrong_simulator_check")),
          "check with $ROBOTARIUM_PYTHON_SIMULATOR naming a folder that is no checkout: " + output)
    # --standin uses neither, as the runner does.
    run_check([dream, "check-submission", export, "--simulator", not_simulator, "--standin", "--out",
               loop.path("standin_anyway_check"), "-q"])
    with open(os.path.join(sim_dir, "run.lcmlog"), "rb") as f:
        check(f.read() == simulated_log, "the simulated run's log changed")

    loop.report.append("bad input: 21 robots, duration cap, injection, NaN, 7-robot result, escaping path: refused; "
                       "an import over its declared duration or robot count: rejected; checks and exports "
                       "into runs' folders: refused")


def once(loop):
    dream = loop.dream
    sim_dir = loop.path("go_to_goal_sim")
    check_dir = loop.path("go_to_goal_check_track")
    # dream compare writes its report and picture.
    output, _ = run([dream, "compare", sim_dir, check_dir, "--out", loop.path("compare")])
    check("tracking error" in output, "compare: " + output)
    for name in ("comparison.json", "comparison.png"):
        check(os.path.isfile(loop.path("compare", name)), "compare wrote no " + name)
    # The agents run unchanged against the lab's poses, through the command.
    # Exit 0, or 5 when the lab run missed go_to_goal's goal: since the stand-in runs the official
    # start-up drive, its lab run starts as the official one does, up to 5 mm off, and can end
    # 0.0200082 m from a goal judged at 0.02 m (docs/robotarium.md#measured), as import judges it too.
    code, output, _ = run_with_code([dream, "lab-replay", check_dir, "--out", loop.path("replay"), "-q"], expect=None)
    check(code in (0, 5), "lab-replay exited %d:\n%s" % (code, output[-2000:]))
    with open(loop.path("replay", "summary.json")) as f:
        summary = json.load(f)
    check(summary["end"] == "finished", "lab-replay: " + summary["reason"])
    check(not summary["robots_ever_lost"], "lab-replay lost agents")
    agreement = summary["lab_replay"]["agents_vs_lab_commands"]
    check(all(a["steps_with_command"] > 0 for a in agreement), "lab-replay: some robot never had a command")
    # lcm-logplayer reads the imported log to its end (bridge_logplayer_replay plays it over udpm).
    run(["lcm-logplayer", "--lcm-url=memq://", "-s", "1000", os.path.join(check_dir, "run.lcmlog")], timeout=60)
    loop.report.append("lcm-logplayer read the imported log to its end")


def respaced_log(source, target, step_us=33000):
    """Copies the log at `source` to `target` with its event stamps a step apart: each DREAM_POSES
    starts the next step's burst. lcm-logplayer paces by these stamps, which in an imported
    stand-in log are the stand-in's clock: on a loaded machine two steps come microseconds apart,
    and three bursts at once overflow lcm-logger's 30-message queue whatever the play speed. The
    messages, their order and their contents (what the test compares) are the imported log's."""
    from dream_log import read_events
    step = 0
    with open(target, "wb") as out:
        for number, event in enumerate(read_events(source)):
            if event.channel == "DREAM_POSES":
                step += 1
            channel = event.channel.encode()
            out.write(struct.pack(">IqqII", 0xEDA1DA01, number, step * step_us, len(channel), len(event.data)) +
                      channel + event.data)


def logplayer(loop):
    """lcm-logplayer plays the imported log over udpm to lcm-logger, which records every DREAM_* message."""
    check_dir = loop.path("go_to_goal_check_track")
    sys.path.insert(0, os.path.join(loop.source, "python"))
    # At the lab's pace (33 ms a step) and real time, as logplayer_replay plays a run log.
    imported_log = loop.path("imported_respaced.lcmlog")
    respaced_log(os.path.join(check_dir, "run.lcmlog"), imported_log)
    integration = os.path.join(loop.source, "tests", "integration")
    output, _ = run([os.path.join(integration, "netns.sh"), sys.executable,
                     os.path.join(integration, "logplayer_replay.py"), "--dream", loop.dream, "--source",
                     loop.source, "--log", imported_log, "--speed", "1"], expect=None, timeout=120)
    if "SKIP" in output:
        raise Skipped(output.strip())
    check("PASS" in output, "lcm-logplayer -> lcm-logger on the imported log: " + output[-2000:])
    loop.report.append("lcm-logplayer -> udpm -> lcm-logger, imported log: " + output.strip().splitlines()[-2])


def equivalence(loop, checkout):
    """The exported script from the same exact start in both simulators gives the same poses."""
    runner = os.path.join(loop.source, "bridge", "python", "run_submission.py")
    upload = loop.path("go_to_goal_export_track", "upload")
    poses = {}
    for kind, flags in (("official", ["--simulator", checkout]), ("standin", ["--standin"])):
        out = loop.path("equivalence_" + kind)
        run([sys.executable, runner, "--upload", upload, "--workdir", out, "--report", out + ".json",
             "--skip-initialization", "--record-poses", out + "_poses.npy"] + flags)
        with open(out + ".json") as f:
            report = json.load(f)
        check(report["ok"] and report["simulator"] == kind, kind + ": " + json.dumps(report)[:2000])
        check(report["verdict"] == "clean", kind + ": verdict " + report["verdict"])
        import numpy as np
        poses[kind] = np.load(out + "_poses.npy")
    import numpy as np
    check(poses["official"].shape == poses["standin"].shape,
          "pose counts differ: %s vs %s" % (poses["official"].shape, poses["standin"].shape))
    worst = float(np.max(np.abs(poses["official"] - poses["standin"])))
    check(worst <= 1e-9, "official and stand-in poses differ by %g" % worst)
    loop.report.append("official vs stand-in from the same start: %d get_poses() calls, largest difference %.3g" %
                       (poses["official"].shape[0], worst))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dream", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--simulator", choices=["standin", "official"], required=True)
    parser.add_argument("--experiments", default=",".join(EXPERIMENTS))
    parser.add_argument("--logplayer", action="store_true",
                        help="only: go_to_goal through the stand-in, then its imported log over udpm (netns)")
    args = parser.parse_args()
    started = time.monotonic()

    def body(tmp, report):
        flags, checkout = simulator_flags(args.simulator, tmp, "to run the bridge in the official simulator")
        loop = Loop(args, tmp, flags)
        loop.report = report
        if args.logplayer:
            loop.experiment("go_to_goal")
            logplayer(loop)
            return "(%.1f s)" % (time.monotonic() - started)
        names = [n for n in args.experiments.split(",")
                 if os.path.isfile(os.path.join(args.source, "config", n + ".yaml"))]
        for name in names:
            loop.experiment(name)
        loop.experiment("go_to_goal", strategy="replay")
        loop.experiment("go_to_goal", barriers=True)
        if args.simulator == "standin":
            once(loop)
            bad_input(loop)
        else:
            equivalence(loop, checkout)
        return "(%.1f s)" % (time.monotonic() - started)

    return drive("dream_bridge_", body)


if __name__ == "__main__":
    sys.exit(main())
