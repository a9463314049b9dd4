#!/usr/bin/python3
"""robotarium_script_export: the upload of a Robotarium script is the script itself, with DREAM's
recorder as its main file (docs/robotarium-scripts.md#the-upload-dream-export-and-dream-check-submission).

- `dream export SCRIPT.py` writes upload/ holding the script byte for byte and dream_record.py (the
  recorder, naming the script), and script_export.json naming the recorder as the main file; `dream
  export RUN` of a script's run folder does the same;
- `dream check-submission` of it runs the recorder, and so the script, in DREAM's stand-in (and, when
  ROBOTARIUM_PYTHON_SIMULATOR is set, in the official simulator, with a matplotlib stub that draws
  nothing): exit 0, check.json with the debug() text and its verdict; the recorder leaves
  dream_result.npy as the lab would return it, and `dream import` of it with the export gives the lab
  run of the script's robots (its steps the script's step() calls, its start the poses after the
  start-up drive, its goal the script's last at_position check, which the recorder kept), and `dream
  lab-replay` of that run runs the script again on the lab's poses, commanding at every step what it
  commanded at the lab; an upload edited after the export is refused;
- a script importing a module the Robotarium lacks is refused, naming it, exit 3, nothing written;
- `dream launch SCRIPT.py` and `dream sim SCRIPT.py` are refused, naming `dream run`.

Skipped (77) without numpy or cvxopt.
Usage: robotarium_script_export.py --dream BIN --source DIR
"""

import json
import os

from dreamtest import arguments, check, main, script_under_test, tail

SCRIPT = """
import numpy as np
import rps.robotarium as robotarium
from rps.utilities.misc import create_at_position
from rps.utilities.transformations import create_si_to_uni_dynamics

N = 2
at_position = create_at_position(position_error=0.2)
r = robotarium.Robotarium(number_of_robots=N, show_figure=False, sim_in_real_time=True,
                          initial_conditions=np.array([[-0.5, 0.5], [0.0, 0.0], [0.0, 0.0]]))
si_to_uni = create_si_to_uni_dynamics()
goals = np.array([[-0.5, 0.5], [0.3, 0.3]])
for _ in range(50):
    x = r.get_poses()
    r.set_velocities(np.arange(N), si_to_uni(0.5 * (goals - x[:2, :]), x))
    r.step()
    at_position(x, goals)
r.debug()
"""
STUB_MATPLOTLIB = {
    "__init__.py": "def use(*a, **k):\n    pass\n",
    "pyplot.py": ("class _Any:\n    def __getattr__(self, name):\n        return self\n"
                  "    def __call__(self, *a, **k):\n        return self\n"
                  "    def __iter__(self):\n        return iter((self, self))\n"
                  "_any = _Any()\n"
                  "def __getattr__(name):\n    return _any\n"),
    "patches.py": "from matplotlib.pyplot import _Any as Rectangle, _Any as PathPatch, _Any as Polygon, _Any as Circle\n",
    "lines.py": "from matplotlib.pyplot import _Any as Line2D\n",
    "path.py": "from matplotlib.pyplot import _Any as Path\n",
}


def check_export(export_dir, script):
    upload = os.path.join(export_dir, "upload")
    check(sorted(os.listdir(upload)) == ["dream_record.py", os.path.basename(script)], f"{upload} holds {os.listdir(upload)}")
    with open(os.path.join(upload, os.path.basename(script)), "rb") as a, open(script, "rb") as b:
        check(a.read() == b.read(), f"{upload}: the script is not uploaded byte for byte")
    with open(os.path.join(export_dir, "script_export.json")) as f:
        manifest = json.load(f)
    check(manifest["main_file"] == "dream_record.py" and manifest["script_file"] == os.path.basename(script) and
          manifest["imports"] == ["numpy", "rps"],
          f"script_export.json: {manifest}")


def check_submission(ctx, args, export_dir, name, extra, env):
    out = ctx.path(name)
    ctx.start(name, [args.dream, "check-submission", export_dir, "--out", out] + extra, env=env)
    code = ctx.wait(name, 600)
    check(code == 0, f"check-submission {' '.join(extra)} of a script's export exited {code}: "
                     f"{tail(ctx.output(name), 1500)}")
    with open(os.path.join(out, "check.json")) as f:
        report = json.load(f)
    check(report["verdict"] in ("clean", "warning") and "Your simulation took" in report["debug_text"],
          f"check.json of a script the lab accepts: {json.dumps(report)[:600]}")
    return report, out


def check_import(ctx, args, export_dir, check_dir, name):
    """The recorder's result, imported as the lab's would be: the script's 2 robots and 50 steps."""
    result = os.path.join(check_dir, "lab_files", "dream_result.npy")
    check(os.path.isfile(result), f"the recorder left no {result}")
    lab = ctx.path(name + "_lab")
    code, output = ctx.run([args.dream, "import", result, "--export", export_dir, "--out", lab], timeout=300)
    check(code == 0, f"dream import of the recorder's result: exit {code}: {tail(output, 1500)}")
    with open(os.path.join(lab, "summary.json")) as f:
        summary = json.load(f)
    check(summary["robots"] == 2 and summary["steps"] == 50 and summary["lab"]["complete"],
          f"the imported run is not the script's: {json.dumps(summary)[:800]}")
    check(summary["lab"]["settle_steps"] > 0, f"no start-up drive in the result: {summary['lab']}")
    goal = summary["goal"]
    check(goal["has_criterion"] and goal["met"] and "at_position check" in goal["detail"],
          f"the imported run is not judged by the script's last check (dream_goal.json): {goal}")
    # lab-replay runs the script again as every robot's agent on the lab's poses: its commands are the lab's.
    replay = ctx.path(name + "_replay")
    code, output = ctx.run([args.dream, "lab-replay", lab, "--out", replay, "-q"], timeout=300)
    check(code == 0, f"lab-replay of a script's lab run: exit {code}: {tail(output, 1500)}")
    with open(os.path.join(replay, "summary.json")) as f:
        agreement = json.load(f)["lab_replay"]["agents_vs_lab_commands"]
    check(len(agreement) == 2 and all(robot["first_different_step"] == -1 and robot["steps_with_command"] == 50
                                      for robot in agreement),
          f"the script on the lab's poses did not command what it commanded at the lab: {agreement}")


def test(ctx):
    args = arguments()
    script = script_under_test(ctx, "upload_me.py", SCRIPT)
    export_dir = ctx.path("export")
    code, output = ctx.run([args.dream, "export", script, "--out", export_dir], timeout=120)
    check(code == 0 and "main file dream_record.py" in output, f"dream export SCRIPT.py: exit {code}: {tail(output)}")
    check_export(export_dir, script)

    standin, standin_dir = check_submission(ctx, args, export_dir, "standin", ["--standin"], None)
    check(standin["simulator"] == "standin", f"--standin ran {standin['simulator']}")
    check_import(ctx, args, export_dir, standin_dir, "standin")
    simulator = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
    if os.path.isfile(os.path.join(simulator, "rps", "robotarium.py")):
        stub = ctx.path("stub", "matplotlib")
        os.makedirs(stub)
        for name, text in STUB_MATPLOTLIB.items():
            with open(os.path.join(stub, name), "w") as f:
                f.write(text)
        official, official_dir = check_submission(ctx, args, export_dir, "official", ["--require-official"],
                                                  dict(os.environ, PYTHONPATH=ctx.path("stub")))
        check_import(ctx, args, export_dir, official_dir, "official")
        check(official["simulator"] == "official", f"--require-official ran {official['simulator']}")
        print("checked in the official simulator too")

    # The folder of a script's run exports its script.
    run_dir = ctx.path("run")
    code, output = ctx.run([args.dream, "run", script, "--out", run_dir, "-q"], timeout=300)
    check(code == 0, f"dream run SCRIPT.py: exit {code}: {tail(output)}")
    code, output = ctx.run([args.dream, "export", run_dir, "--out", ctx.path("export_of_run")], timeout=120)
    check(code == 0, f"dream export of a script's run folder: exit {code}: {tail(output)}")
    check_export(ctx.path("export_of_run"), script)

    # An upload edited after the export is refused.
    with open(os.path.join(export_dir, "upload", "upload_me.py"), "a") as f:
        f.write("# edited\n")
    code, output = ctx.run([args.dream, "check-submission", export_dir, "--standin", "--out", ctx.path("edited")],
                           timeout=120)
    check(code == 1 and "edited after the export" in output, f"an edited upload: exit {code}: {tail(output)}")

    # What the Robotarium lacks is refused, nothing written.
    foreign = ctx.path("foreign.py")
    with open(foreign, "w") as f:
        f.write("import numpy as np\nimport not_on_the_robotarium.sub\n" + SCRIPT)
    code, output = ctx.run([args.dream, "export", foreign, "--out", ctx.path("foreign_export")], timeout=120)
    check(code == 3 and "not_on_the_robotarium" in output and "nothing was written" in output,
          f"a script importing a module the Robotarium lacks: exit {code}: {tail(output)}")
    check(not os.path.exists(ctx.path("foreign_export")), "a refused export wrote its folder")

    for command in ("launch", "sim"):
        code, output = ctx.run([args.dream, command, script], timeout=60)
        check(code == 1 and f"dream run {script}" in output, f"dream {command} SCRIPT.py: exit {code}: {tail(output)}")


if __name__ == "__main__":
    main(test)
