#!/usr/bin/python3
"""`dream export --strategy controller`: the Python controller itself in the submission.

    bridge_controller_strategy.py --dream build/dream --source . --types-dir build/python \
        --simulator standin|official

Each case runs a Python-controller config with `dream run`, exports it with the controller
strategy, runs the submission with run_submission.py --skip-initialization (exactly at the
start poses, as the simulated run starts) in a Robotarium simulator, imports the result and
compares it with the simulated run:

  - go_to_goal_python (8 robots, a moving obstacle, stops when every robot is done) and
    hrvo_circle_python (10 robots, radios, movement sensors, periods and start delays): the
    same poses at every step to 1e-9, the same step count and the same violation counts,
    the obstacles handed to the controllers equal to those the simulator published; the
    upload folder holds flat files only, UPLOAD.txt lists each, the script is the fixed
    template, the runtime is flattened (no relative import left, no LCM module shipped);
    dream compare and dream lab-replay take the imported run;
  - a controller that raises at step 40 for robot 2: the script runs to its last step, the
    error is printed once with the robot's id, the robot holds still from that step, and the
    poses still equal the simulated run's (where the world stopped the lost robot);
  - a hostile config string (in a controller key and the description): the script is still
    the template, the spec travels as uint8 JSON, and nothing of the string runs;
  - dream check-submission (with the simulator's start-up drive) replays the lab run against the
    controllers as agents: go_to_goal_python's send what the submission sent (check.json's
    controllers_on_lab_poses.same_commands, exit 0); a controller drawing unseeded random numbers
    does not (a warning naming the robot and step, exit 5); a track export has no such replay;
    SIGINT while the script runs ends the check with exit 130, said as an interruption;
  - refusals: a C++ kind with --strategy controller (exit 3, naming --strategy track, nothing
    written); controller module names that would clash with the submission's files or the
    modules it imports (exit 1, naming controller.module); track still works for a Python kind.

With --simulator official the checkout comes from $ROBOTARIUM_PYTHON_SIMULATOR (a checkout or
a bare git repository); without it the test prints SKIP and exits 77. It then also compares
the official simulator's poses with the stand-in's for the same submission.
"""

import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

TOLERANCE = 1e-9
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from bridge_driver import check, drive, simulator_flags  # noqa: E402
from bridge_roundtrip import run  # noqa: E402

FAULTY_CONTROLLER = '''"""A test controller: drives slowly on a curve; robot `fail_robot` raises from `fail_step` on."""

from dream import Robot, key


class Faulty(Robot):
    KEYS = {"fail_robot": key(-1, kind="int"),
            "fail_step": key(0, kind="int"),
            "label": key("", kind="string")}

    def update(self, step):
        if self.id == self.config["fail_robot"] and step >= self.config["fail_step"]:
            raise ZeroDivisionError("robot %d gives up at step %d" % (self.id, step))
        return (0.05, 0.3 * (self.id - 1))
'''

FAULTY_CONFIG = '''name: faulty_python
description: {description}
seed: 1
robots: 3
steps: 80
stop_when_done: false
world:
  mode: lockstep
initial_poses:
  - [-0.5, -0.4, 0.0]
  - [-0.5, 0.0, 0.0]
  - [-0.5, 0.4, 0.0]
obstacles:
  - center: [0.8, 0.6]
    size: [0.2, 0.2]
    path: {{waypoints: [[0.8, -0.6]], speed_mps: 0.05, mode: ping_pong}}
controller:
  kind: python
  module: {module}
  class: Faulty
  fail_robot: 2
  fail_step: 40
  label: {label}
'''


class Case:
    def __init__(self, args, tmp, simulator_flags):
        self.args = args
        self.dream = args.dream
        self.tmp = tmp
        self.flags = simulator_flags
        # check-submission takes the same choice of simulator, not run_submission.py's flags.
        self.check_flags = ["--standin"] if simulator_flags == ["--standin"] else \
            ["--require-official", "--simulator", simulator_flags[-1]]
        self.report = []
        sys.path.insert(0, os.path.join(args.source, "python"))
        import dream_log
        self.dream_log = dream_log

    def path(self, *parts):
        return os.path.join(self.tmp, *parts)

    def write_controller(self, name, module_text, config_text):
        """<name>/<name>.py and <name>/<name>.yaml; the config's path."""
        folder = self.path(name)
        os.makedirs(folder, exist_ok=True)
        with open(os.path.join(folder, name + ".py"), "w") as f:
            f.write(module_text)
        config = os.path.join(folder, name + ".yaml")
        with open(config, "w") as f:
            f.write(config_text)
        return config

    def simulate(self, config, name, expect=0):
        sim_dir = self.path(name + "_sim")
        run([self.dream, "run", config, "--out", sim_dir, "-q"], expect=expect)
        return sim_dir

    def export(self, sim_dir, name, strategy="controller", expect=0, extra=()):
        export_dir = self.path(name + "_export_" + strategy)
        output, _ = run([self.dream, "export", sim_dir, "--out", export_dir, "--strategy", strategy, "-q"] +
                        list(extra), expect=expect)
        return export_dir, output

    def run_script(self, export_dir, name, flags=None):
        """The submission from its exact start poses; (report, stdout, recorded poses)."""
        import numpy as np
        workdir = self.path(name + "_lab")
        report_path = workdir + ".json"
        poses_path = workdir + "_poses.npy"
        run([sys.executable, os.path.join(self.args.source, "bridge", "python", "run_submission.py"), "--upload",
             os.path.join(export_dir, "upload"), "--workdir", workdir, "--report", report_path,
             "--skip-initialization", "--record-poses", poses_path] + (self.flags if flags is None else flags))
        with open(report_path) as f:
            report = json.load(f)
        with open(os.path.join(workdir, "stdout.txt")) as f:
            stdout = f.read()
        check(report["ok"], name + ": the script failed: %s\n%s" % (report["error"], stdout[-2000:]))
        return report, stdout, np.load(poses_path), workdir

    def import_result(self, workdir, export_dir, name, expect=0):
        lab_dir = self.path(name + "_imported")
        run([self.dream, "import", os.path.join(workdir, "dream_result.npy"), "--export", export_dir, "--out",
             lab_dir], expect=expect)
        return lab_dir

    def load(self, run_dir):
        return self.dream_log.load(run_dir, self.args.types_dir)

    def same_run(self, sim_dir, lab_dir, name):
        """Poses at every step within TOLERANCE, the same steps and violation counts; the largest difference."""
        import numpy as np
        simulated = self.load(sim_dir)
        lab = self.load(lab_dir)
        check(simulated.poses.shape == lab.poses.shape,
              "%s: the simulated run has %s poses, the lab run %s" % (name, simulated.poses.shape, lab.poses.shape))
        worst = float(np.max(np.abs(simulated.poses - lab.poses)))
        check(worst <= TOLERANCE, "%s: poses differ from the simulated run's by %g (step %d)" %
              (name, worst, int(np.argmax(np.max(np.abs(simulated.poses - lab.poses), axis=(1, 2))))))
        with open(os.path.join(sim_dir, "summary.json")) as f:
            sim_violations = json.load(f)["violations"]
        with open(os.path.join(lab_dir, "summary.json")) as f:
            lab_violations = json.load(f)["violations"]
        check(sim_violations == lab_violations,
              "%s: violations differ: simulated %s, lab %s" % (name, sim_violations, lab_violations))
        return simulated, lab, worst

    def upload_listing(self, export_dir, name):
        """Every file of upload/ is a flat .py/.npy file and UPLOAD.txt names each."""
        upload = os.path.join(export_dir, "upload")
        files = sorted(os.listdir(upload))
        with open(os.path.join(export_dir, "UPLOAD.txt")) as f:
            instructions = f.read()
        for file_name in files:
            check(os.path.isfile(os.path.join(upload, file_name)), name + ": upload/ holds a folder " + file_name)
            check(file_name.endswith((".py", ".npy")), name + ": upload/ holds " + file_name)
            check("  " + file_name + "\n" in instructions or "  " + file_name + "    <-" in instructions,
                  name + ": UPLOAD.txt does not list " + file_name)
        check("(%d files, no folders)" % len(files) in instructions, name + ": UPLOAD.txt's file count")
        return files


def experiment(case, name, module):
    """A Python-controller config of config/: export, submission, import; the same run."""
    import numpy as np
    source = case.args.source
    sim_dir = case.simulate(os.path.join(source, "config", name + ".yaml"), name)
    export_dir, _ = case.export(sim_dir, name)
    files = case.upload_listing(export_dir, name)
    runtime = ["dream.py"] + ["dream_%s.py" % m for m in ("robot", "motion", "drawing", "sensors", "radios", "timer",
                                                          "robot_agent", "controller_spec", "hrvo", "barriers",
                                                          "toolbox_checks", "transformations", "controllers", "graph",
                                                          "misc")]
    expected = sorted(["dream_main.py", "dream_params.npy", "dream_initial_poses.npy", "dream_controller_spec.npy",
                       "dream_obstacles.npy", module] + runtime)
    check(files == expected, "%s: upload/ holds %s, expected %s" % (name, files, expected))
    upload = os.path.join(export_dir, "upload")
    with open(os.path.join(upload, "dream_main.py")) as f, \
            open(os.path.join(source, "bridge", "python", "dream_main.py")) as g:
        check(f.read() == g.read(), "the exported script differs from the fixed template")
    for file_name in runtime:
        with open(os.path.join(upload, file_name)) as f:
            text = f.read()
        check("from ." not in text and "import dream." not in text, file_name + " still imports relatively")
    with open(os.path.join(upload, module)) as f, open(os.path.join(source, "config", "python", module)) as g:
        check(f.read() == g.read(), name + ": the controller module was not copied as it is")

    report, stdout, poses, workdir = case.run_script(export_dir, name)
    check(report["verdict"] == "clean", name + ": debug() verdict " + report["verdict"])
    lab_dir = case.import_result(workdir, export_dir, name)
    simulated, lab, worst = case.same_run(sim_dir, lab_dir, name)
    check(lab.final_state == "FINISHED", name + ": imported run ends " + str(lab.final_state))
    # The obstacles the script hands the controllers are the simulator's, step for step.
    obstacles = np.load(os.path.join(upload, "dream_obstacles.npy"), allow_pickle=False)
    for k in range(simulated.num_steps):
        check(np.array_equal(obstacles[k], simulated.obstacles[k].reshape(obstacles[k].shape)),
              "%s: step %d: dream_obstacles.npy %s, the simulator published %s" %
              (name, k, obstacles[k].tolist(), simulated.obstacles[k].tolist()))
    case.report.append("%s (%s): %d steps, poses equal to the simulated run's within %.3g, same violations, "
                       "%d obstacles as the simulator moved them" %
                       (name, report["simulator"], simulated.num_steps - 1, worst, obstacles.shape[1]))
    return sim_dir, export_dir, lab_dir, poses


def go_to_goal(case):
    sim_dir, export_dir, lab_dir, poses = experiment(case, "go_to_goal_python", "go_to_goal.py")
    # compare and lab-replay take the imported run as any other.
    output, _ = run([case.dream, "compare", sim_dir, lab_dir, "--out", case.path("compare")])
    check("tracking error" in output, "compare: " + output[-1000:])
    check("first (simulation): " in output and "second (lab run (dream import)): " in output,
          "compare names the simulated run and the imported one: " + output[:400])
    run([case.dream, "lab-replay", lab_dir, "--out", case.path("lab_replay"), "-q"])
    output, _ = run([case.dream, "compare", lab_dir, case.path("lab_replay"), "--out", case.path("compare_replay")])
    check("first (lab run (dream import)): " in output and "second (lab replay (dream lab-replay)): " in output,
          "compare names the imported run and its lab replay: " + output[:400])
    with open(case.path("lab_replay", "summary.json")) as f:
        replay = json.load(f)
    check(replay["end"] == "finished", "lab-replay: " + replay["reason"])
    return export_dir, poses


JITTER_CONTROLLER = '''"""A test controller no one can reproduce: unseeded random turn rates."""

import random

from dream import Robot


class Jitter(Robot):
    def update(self, step):
        return (0.05, random.uniform(-0.5, 0.5))
'''

JITTER_CONFIG = '''name: jitter_python
seed: 1
robots: 2
steps: 60
stop_when_done: false
initial_poses:
  - [-0.5, -0.3, 0.0]
  - [-0.5, 0.3, 0.0]
controller:
  kind: python
  module: jitter.py
  class: Jitter
'''


def controllers_on_lab_poses(case, export_dir, name, expect):
    """dream check-submission on an export; its check.json and output."""
    check_dir = case.path(name + "_check")
    output, _ = run([case.dream, "check-submission", export_dir, "--out", check_dir] + case.check_flags,
                    expect=expect)
    with open(os.path.join(check_dir, "check.json")) as f:
        return json.load(f), output


def check_submission(case, go_to_goal_export):
    # The same controllers on the lab's poses send what the submission sent.
    report, output = controllers_on_lab_poses(case, go_to_goal_export, "go_to_goal_python", expect=0)
    replayed = report.get("controllers_on_lab_poses", {})
    check(replayed.get("replayed") is True and replayed.get("same_commands") is True and replayed["steps"] >= 200,
          "check-submission: go_to_goal_python's controllers on the lab's poses: %s\n%s" % (replayed, output[-2000:]))
    check(replayed["max_v_difference_mps"] <= TOLERANCE and replayed["max_w_difference_radps"] <= TOLERANCE,
          "check-submission: command differences %s" % replayed)
    check("your controllers on the lab's poses send what the submission sent" in output,
          "check-submission does not say the controllers agree: " + output[-2000:])
    agreeing = max(replayed["max_v_difference_mps"], replayed["max_w_difference_radps"])
    # An earlier check's lab_files/ does not make a broken upload pass, nor its replay outlive it.
    check_dir = case.path("go_to_goal_python_check")
    broken = case.path("broken_export")
    shutil.copytree(go_to_goal_export, broken)
    os.remove(os.path.join(broken, "upload", "dream_timer.py"))
    # Issue 23: start poses moved by 0.3 m after the export passed the check clean; the export's
    # digests name the edited file before anything runs ...
    import numpy as np
    moved = case.path("moved_export")
    shutil.copytree(go_to_goal_export, moved)
    poses_path = os.path.join(moved, "upload", "dream_initial_poses.npy")
    poses = np.load(poses_path, allow_pickle=False)
    poses[0, 0] += 0.3
    np.save(poses_path, poses)
    output, _ = run([case.dream, "check-submission", moved, "--out", case.path("moved_check")] + case.check_flags,
                    expect=1)
    check("upload/dream_initial_poses.npy: changed after the export" in output,
          "a check of an upload whose start poses were edited: " + output[-1500:])
    # ... and a missing file
    output, _ = run([case.dream, "check-submission", broken, "--out", check_dir, "--overwrite"] + case.check_flags,
                    expect=1)
    check("upload/dream_timer.py: missing" in output, "a check of an upload without dream_timer.py: " + output[-1500:])
    # ... and with them edited too, the script fails in the simulator.
    manifest_path = os.path.join(broken, "export.json")
    with open(manifest_path) as f:
        manifest = json.load(f)
    del manifest["upload_sha256"]["dream_timer.py"]
    with open(manifest_path, "w") as f:
        json.dump(manifest, f)
    output, _ = run([case.dream, "check-submission", broken, "--out", check_dir, "--overwrite"] + case.check_flags,
                    expect=4)
    check("dream_timer" in output, "a check of an upload without dream_timer.py: " + output[-1500:])
    check(not os.path.exists(os.path.join(check_dir, "lab_replay")), "the earlier check's replay was kept")
    # Unseeded randomness: the replay's commands differ from the submission's.
    config = case.write_controller("jitter", JITTER_CONTROLLER, JITTER_CONFIG)
    sim_dir = case.simulate(config, "jitter")
    export_dir, _ = case.export(sim_dir, "jitter")
    report, output = controllers_on_lab_poses(case, export_dir, "jitter", expect=5)
    replayed = report["controllers_on_lab_poses"]
    check(replayed["replayed"] is True and replayed["same_commands"] is False and
          replayed["max_w_difference_radps"] > 1e-3,
          "check-submission: a random controller's commands were found equal: %s" % replayed)
    check("WARNING: your controllers decided differently on the lab's poses" in output and
          re.search(r"robot [01] from step [0-9]+ \(largest difference", output),
          "check-submission: no warning naming robot and step for a random controller: " + output[-2000:])
    # A track export drove the lab with the tracker's commands: nothing to replay.
    track_dir, _ = case.export(case.path("go_to_goal_python_sim"), "go_to_goal_python", strategy="track")
    report, output = controllers_on_lab_poses(case, track_dir, "go_to_goal_python_track", expect=0)
    check("controllers_on_lab_poses" not in report, "check-submission replayed a track export: %s" % report)
    case.report.append("check-submission: go_to_goal_python's controllers send on the lab's poses what the "
                       "submission sent (largest difference %.3g); a random controller is caught (exit 5)"
                       % agreeing)


SLOW_CONTROLLER = '''"""A test controller that takes DREAM_TEST_STEP_S seconds a step (none when unset)."""

import os
import time

from dream import Robot


class Slow(Robot):
    def update(self, step):
        time.sleep(float(os.environ.get("DREAM_TEST_STEP_S", "0")))
        return (0.02, 0.0)
'''


def interrupted_check(case):
    """Ctrl-C while the submission runs: exit 130, said as an interruption, not as a failed script."""
    config = case.write_controller(
        "slow", SLOW_CONTROLLER,
        JITTER_CONFIG.replace("jitter", "slow").replace("Jitter", "Slow").replace("steps: 60", "steps: 600"))
    sim_dir = case.simulate(config, "slow")
    export_dir, _ = case.export(sim_dir, "slow")
    check_dir = case.path("slow_check")
    # Slow only in the submission (the simulated run above took no time).
    process = subprocess.Popen([case.dream, "check-submission", export_dir, "--out", check_dir] + case.check_flags,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               env=dict(os.environ, DREAM_TEST_STEP_S="0.02"))
    time.sleep(3.0)  # the script is running (600 steps of 2 robots at 20 ms: about 24 s)
    check(process.poll() is None, "check-submission of the slow controller ended before the interruption")
    process.send_signal(signal.SIGINT)
    output, _ = process.communicate(timeout=30)
    check(process.returncode == 130, "check-submission exited %d after SIGINT, expected 130:\n%s" %
          (process.returncode, output[-2000:]))
    check("interrupted while the script ran" in output and "the script failed" not in output,
          "check-submission does not say it was interrupted:\n" + output[-2000:])
    case.report.append("check-submission interrupted while the script ran: exit 130")


def faulty(case, label='"a plain label"', description="a controller that fails"):
    folder = case.path("faulty")
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "faulty.py"), "w") as f:
        f.write(FAULTY_CONTROLLER)
    config = os.path.join(folder, "faulty.yaml")
    with open(config, "w") as f:
        f.write(FAULTY_CONFIG.format(description=description, module="faulty.py", label=label))
    return config


def failing_controller(case):
    import numpy as np
    config = faulty(case)
    # The simulated run loses robot 2 at step 40 and fails (exit 4) but records every step.
    sim_dir = case.simulate(config, "faulty", expect=4)
    # Refused as it is (the lab would run a controller known to fail), exported with --force.
    _, output = case.export(sim_dir, "faulty", expect=3)
    check("lost_robot: robot 2" in output and "ZeroDivisionError" in output,
          "faulty: the refusal does not name robot 2 and its error: " + output)
    export_dir, output = case.export(sim_dir, "faulty", extra=["--force"])
    check("WARNING: lost_robot: robot 2" in output, "faulty: --force does not warn of the lost robot: " + output)
    report, stdout, poses, workdir = case.run_script(export_dir, "faulty")
    check(report["finished_line"].startswith("DREAM: finished: 3 robots, 80 experiment steps"),
          "faulty: the script did not run to its end: " + report["finished_line"])
    lines = [line for line in stdout.splitlines() if "its controller failed" in line]
    check(len(lines) == 1 and lines[0].startswith("DREAM: robot 2 holds still from step 40 on") and
          "ZeroDivisionError: robot 2 gives up at step 40" in lines[0],
          "faulty: the error is not printed once with the robot id: %s" % lines)
    result = np.load(os.path.join(workdir, "dream_result.npy"))
    experiment = result[result[:, 0] == 1.0]
    n = 3
    v, w = experiment[:, 3 + 3 * n + 2], experiment[:, 3 + 4 * n + 2]
    check(np.all(v[40:] == 0.0) and np.all(w[40:] == 0.0) and np.all(v[1:40] == 0.05),
          "faulty: robot 2's commands are not (0, 0) from step 40 on")
    # Within rounding: the simulator wraps every heading with atan2 each step, which may move a
    # still robot's heading by an ulp once.
    still = np.abs(poses[41:, :, 2] - poses[40, :, 2]).max()
    check(still < 1e-12, "faulty: robot 2 moved %.3g after its controller failed" % still)
    check(np.any(poses[41:, :, 1] != poses[40, :, 1]), "faulty: the other robots stopped as well")
    lab_dir = case.import_result(workdir, export_dir, "faulty")
    _, _, worst = case.same_run(sim_dir, lab_dir, "faulty")
    case.report.append("raising controller: the script ran its 80 steps, robot 2 held still from step 40, the "
                       "error printed once; poses equal to the simulated run's within %.3g" % worst)


def injection(case):
    import numpy as np
    marker = case.path("PWNED")
    payload = "x'''\\\"\\\"\\\"\\n__import__('os').system('touch %s') # {0} %%s ${HOME}" % marker
    config = faulty(case, label='"%s"' % payload, description='"%s"' % payload)
    with open(config) as f:
        check(payload in f.read(), "the injection test did not put its payload into the config")
    sim_dir = case.simulate(config, "hostile", expect=4)
    check(not os.path.exists(marker), "code from the config ran in dream run")
    export_dir, _ = case.export(sim_dir, "hostile", extra=["--force"])
    upload = os.path.join(export_dir, "upload")
    with open(os.path.join(upload, "dream_main.py")) as f, \
            open(os.path.join(case.args.source, "bridge", "python", "dream_main.py")) as g:
        check(f.read() == g.read(), "hostile: the exported script differs from the fixed template")
    for name in os.listdir(upload):
        if name.endswith(".py") and name != "faulty.py":
            with open(os.path.join(upload, name)) as f:
                check("PWNED" not in f.read(), "hostile: the payload reached " + name)
    spec_array = np.load(os.path.join(upload, "dream_controller_spec.npy"), allow_pickle=False)
    check(spec_array.dtype == np.uint8 and spec_array.ndim == 1, "hostile: the spec is not uint8 bytes")
    spec = json.loads(spec_array.tobytes().decode("utf-8"))
    check(spec["params"]["label"]["value"] == payload.replace("\\\"", "\"").replace("\\n", "\n"),
          "hostile: the spec does not carry the label as data: %r" % spec["params"]["label"]["value"])
    check(spec["module"] == "faulty.py", "hostile: spec module " + spec["module"])
    case.run_script(export_dir, "hostile", flags=["--standin"])
    check(not os.path.exists(marker), "code from the config ran in the submission: %s exists" % marker)
    case.report.append("injection: the script is the template, the payload stayed data, nothing ran")


def refusals(case):
    source = case.args.source
    # A C++ kind: refused with the advice, nothing written.
    cpp_dir = case.path("go_to_goal_cpp_sim")
    run([case.dream, "run", os.path.join(source, "config", "go_to_goal.yaml"), "--out", cpp_dir, "--steps", "30",
         "-q"])
    out = case.path("cpp_export")
    output, _ = run([case.dream, "export", cpp_dir, "--out", out, "--strategy", "controller"], expect=3)
    check("strategy:" in output and "is C++" in output and "--strategy track" in output and "kind: python" in output,
          "C++ kind with --strategy controller: " + output)
    check(not os.path.exists(out), "a refused export wrote files")
    # Module names the submission cannot hold: its own files, a module the script imports.
    sim_dir = case.path("faulty_sim")
    folder = case.path("faulty")
    for module in ("dream_robot.py", "numpy.py", "json.py"):
        shutil.copyfile(os.path.join(folder, "faulty.py"), os.path.join(folder, module))
        config = os.path.join(folder, "clash.yaml")
        with open(config, "w") as f:
            f.write(FAULTY_CONFIG.format(description="clash", module=module, label="x"))
        out = case.path("clash_export")
        output, _ = run([case.dream, "export", sim_dir, "--out", out, "--strategy", "controller", "--force",
                         "--config", config], expect=1)
        check("controller.module" in output and module in output and "rename" in output,
              "module %s: %s" % (module, output))
        check(not os.path.exists(out), "a refused export wrote files")
        os.remove(os.path.join(folder, module))
    # track still works for a Python kind; exported into the controller export's folder, its
    # upload/ holds its own files only (UPLOAD.txt says to upload every file there).
    controller_export = case.path("go_to_goal_python_export_controller")
    run([case.dream, "export", case.path("go_to_goal_python_sim"), "--out", controller_export, "--strategy", "track",
         "-q"])
    files = case.upload_listing(controller_export, "track over controller")
    check(files == sorted(["dream_main.py", "dream_params.npy", "dream_initial_poses.npy",
                           "dream_reference_poses.npy", "dream_reference_commands.npy"]),
          "an export into an earlier export's folder left its files: %s" % files)
    export_dir, _ = case.export(case.path("go_to_goal_python_sim"), "go_to_goal_python", strategy="track")
    report, _, _, _ = case.run_script(export_dir, "go_to_goal_python_track", flags=["--standin"])
    check(report["verdict"] == "clean", "track on a Python kind: verdict " + report["verdict"])
    case.report.append("refused: a C++ kind (exit 3, advice --strategy track), module names dream_robot.py, "
                       "numpy.py, json.py (exit 1); track works for a Python kind, also over a controller export")


def tampered_files(case):
    """Issue 23: an upload file edited into something no export writes (deeply nested JSON, a
    pickle, a file cut short) failed in the lab's Python with a raw traceback; the script says
    DREAM: and names the file instead."""
    import pickle

    import numpy as np
    spec_file = "dream_controller_spec.npy"
    export_dir, _ = case.export(case.path("go_to_goal_python_sim"), "tampered_source")

    def nested(upload):
        text = "[" * 100000 + "]" * 100000
        np.save(os.path.join(upload, spec_file), np.frombuffer(text.encode(), dtype=np.uint8))

    def nested_under_the_limit_of_python(upload):
        spec = json.loads(np.load(os.path.join(upload, spec_file)).tobytes())
        spec["params"]["deep"] = {"value": json.loads("[" * 500 + "]" * 500), "line": 1}
        np.save(os.path.join(upload, spec_file), np.frombuffer(json.dumps(spec).encode(), dtype=np.uint8))

    def pickled_spec(upload):
        np.save(os.path.join(upload, spec_file), np.array([{"module": "x.py"}], dtype=object), allow_pickle=True)

    def pickle_as_params(upload):
        with open(os.path.join(upload, "dream_params.npy"), "wb") as f:
            f.write(pickle.dumps({"steps": 10}))

    def cut(name, keep=None):
        def cut_file(upload):
            path = os.path.join(upload, name)
            with open(path, "rb") as f:
                data = f.read()
            with open(path, "wb") as f:
                f.write(data[:keep if keep is not None else len(data) // 2])
        return cut_file

    cases = [("nested JSON", nested, spec_file), ("JSON 500 levels deep", nested_under_the_limit_of_python, "nested"),
             ("a pickled spec", pickled_spec, spec_file), ("a pickle as params", pickle_as_params, "dream_params.npy"),
             ("spec cut short", cut(spec_file), spec_file), ("params cut short", cut("dream_params.npy"), "dream_params.npy"),
             ("params header cut", cut("dream_params.npy", 30), "dream_params.npy"),
             ("start poses cut short", cut("dream_initial_poses.npy"), "dream_initial_poses.npy"),
             ("obstacles cut short", cut("dream_obstacles.npy"), "dream_obstacles.npy")]
    for label, tamper, named in cases:
        upload = case.path("tampered", label.replace(" ", "_"))
        shutil.copytree(os.path.join(export_dir, "upload"), upload)
        tamper(upload)
        workdir = upload + "_lab"
        report_path = workdir + ".json"
        run([sys.executable, os.path.join(case.args.source, "bridge", "python", "run_submission.py"), "--upload",
             upload, "--workdir", workdir, "--report", report_path, "--skip-initialization"] + case.flags, expect=None)
        with open(report_path) as f:
            report = json.load(f)
        error = report.get("error") or ""
        check(not report["ok"] and "DREAM: " in error and "Traceback" not in error and named in error,
              "%s: the script did not fail with a DREAM: message naming %s: %s %s" % (label, named, error[-1500:], report))
    case.report.append("tampered upload files (nested JSON, pickles, cut files): %d cases, each a DREAM: message "
                       "naming the file" % len(cases))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dream", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--types-dir", required=True, help="lcm-gen's Python types (build/python)")
    parser.add_argument("--simulator", choices=["standin", "official"], required=True)
    args = parser.parse_args()

    def body(tmp, report):
        flags, _ = simulator_flags(args.simulator, tmp, "to run the controller strategy in the official simulator")
        case = Case(args, tmp, flags)
        case.report = report
        export_dir, poses = go_to_goal(case)
        if os.path.isfile(os.path.join(args.source, "config", "hrvo_circle_python.yaml")):
            experiment(case, "hrvo_circle_python", "hrvo_circle.py")  # radios, sensors, periods, delays
        failing_controller(case)
        check_submission(case, export_dir)
        interrupted_check(case)
        if args.simulator == "official":
            import numpy as np
            _, _, standin_poses, _ = case.run_script(export_dir, "go_to_goal_python_standin", flags=["--standin"])
            check(standin_poses.shape == poses.shape, "official and stand-in pose counts differ")
            worst = float(np.max(np.abs(standin_poses - poses)))
            check(worst <= TOLERANCE, "official and stand-in poses differ by %g" % worst)
            report.append("official vs stand-in, same submission: largest difference %.3g" % worst)
        else:
            injection(case)
            refusals(case)
            tampered_files(case)
        return ""

    return drive("dream_controller_strategy_", body)


if __name__ == "__main__":
    sys.exit(main())
