#!/usr/bin/python3
"""Run an exported Robotarium submission in a Robotarium Python simulator.

Used by `dream check-submission` (docs/robotarium.md); standard library only,
plus numpy for the simulator. It copies the submission's files into a fresh
working folder, runs the main script there as the lab would (`python
dream_main.py` in the folder holding the data files), and writes a JSON report:
which simulator ran, whether the script finished, every Python warning, and the
text debug() printed with its verdict. The script's output goes to stdout.txt
in the working folder (as the lab returns it); --echo prints it as well.

Simulator: --simulator PATH (a robotarium_python_simulator checkout), else
$ROBOTARIUM_PYTHON_SIMULATOR, else an installed `rps` package, else DREAM's
stand-in (bridge/python/standin) -- unless --require-official, which then
exits with NOT_FOUND.

Exit: 0 the script ran to the end (see the report for its verdict), 1 it
failed, 2 usage, NOT_FOUND (5) no official simulator although required.
"""

import argparse
import contextlib
import io
import json
import os
import random
import runpy
import shutil
import sys
import time
import traceback
import warnings

NOT_FOUND = 5
HERE = os.path.dirname(os.path.abspath(__file__))
STANDIN = os.path.join(HERE, "standin")
MAIN_SCRIPT = "dream_main.py"
UPLOAD_SUFFIXES = (".py", ".npy", ".mat", ".png", ".jpg")
# The start-up drive's step budget (198 s); DREAM's C++ drive (world::StartupDrive) reads this
# line when it is built, so the number is written here only.
STARTUP_MAX_STEPS = 6000


class StartupTimeout(Exception):
    """The start-up drive used up its step budget."""

    def __init__(self, steps):
        super().__init__(steps)
        self.steps = steps


class Tee(io.TextIOBase):
    """Keeps what the script prints, and echoes it when asked to."""

    def __init__(self, stream):
        self.stream = stream
        self.copy = io.StringIO()

    def write(self, text):
        self.copy.write(text)
        if self.stream is not None:
            self.stream.write(text)
        return len(text)

    def flush(self):
        if self.stream is not None:
            self.stream.flush()


def installed_rps():
    """True if an `rps` package other than the stand-in is importable as installed."""
    try:
        import importlib.util
        spec = importlib.util.find_spec("rps")
    except (ImportError, ValueError):
        return False
    return spec is not None and not (spec.origin or "").startswith(STANDIN)


def choose_simulator(args):
    """(kind, path): ('official', checkout or '') or ('standin', STANDIN); None if required and missing."""
    if args.standin:
        return "standin", STANDIN
    path = args.simulator or os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
    if path:
        if not os.path.isfile(os.path.join(path, "rps", "robotarium.py")):
            raise SystemExit("run_submission: %s has no rps/robotarium.py; pass a checkout of "
                             "robotarium/robotarium_python_simulator" % path)
        return "official", os.path.abspath(path)
    if installed_rps():
        return "official", ""
    if args.require_official:
        return None
    return "standin", STANDIN


def verdict_of(text):
    if "Errors detected, your script will NOT run on the Robotarium!" in text:
        return "rejected"
    if "No hard errors detected" in text:
        return "warning"
    if "No errors or warnings in your simulation!" in text:
        return "clean"
    return "unknown"


def debug_text(text):
    start = text.rfind("Your simulation took approximately")
    if start < 0:
        return ""
    end = text.find("DREAM: finished", start)
    return text[start:end if end >= 0 else len(text)].rstrip("\n") + "\n"


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--upload", required=True, help="folder with the files to upload (the export's upload/)")
    parser.add_argument("--workdir", required=True, help="new folder to run in; the script's outputs land here")
    parser.add_argument("--report", required=True, help="JSON report to write")
    parser.add_argument("--simulator", default="", help="robotarium_python_simulator checkout")
    parser.add_argument("--standin", action="store_true", help="use DREAM's stand-in even if the official one exists")
    parser.add_argument("--require-official", action="store_true", help="exit 5 when no official simulator is found")
    parser.add_argument("--skip-initialization", action="store_true",
                        help="start exactly at the initial conditions (both simulators; for comparing them)")
    parser.add_argument("--record-poses", default="", help="save every get_poses() result here (.npy, K x 3 x N)")
    parser.add_argument("--seed", type=int, default=0, help="seeds Python's and numpy's random generators")
    parser.add_argument("--echo", action="store_true", help="print the script's output as it runs")
    parser.add_argument("--main", default=MAIN_SCRIPT,
                        help="the main file in the upload (default %s; a Robotarium script's export: the script)" %
                        MAIN_SCRIPT)
    parser.add_argument("--no-pacing", action="store_true",
                        help="sim_in_real_time=False whatever the script asks (the poses are the same, only sooner)")
    parser.add_argument("--startup-max-steps", type=int, default=STARTUP_MAX_STEPS,
                        help="give up when the simulator's start-up drive takes more steps (default %d = %.0f s)" %
                        (STARTUP_MAX_STEPS, STARTUP_MAX_STEPS * 0.033))
    return parser.parse_args()


def main():
    args = parse_arguments()

    # The script runs in its working folder: make every path absolute first.
    for name in ("upload", "workdir", "report", "record_poses", "simulator"):
        if getattr(args, name):
            setattr(args, name, os.path.abspath(getattr(args, name)))
    chosen = choose_simulator(args)
    if chosen is None:
        print("run_submission: no official Robotarium simulator: pass --simulator, set "
              "ROBOTARIUM_PYTHON_SIMULATOR or pip-install robotarium_python_simulator")
        return NOT_FOUND
    kind, path = chosen

    upload = args.upload
    if os.path.basename(args.main) != args.main or not os.path.isfile(os.path.join(upload, args.main)):
        raise SystemExit("run_submission: %s has no %s" % (upload, args.main))
    workdir = args.workdir
    os.makedirs(workdir, exist_ok=True)
    for stale in ("dream_result.npy", "dream_result.partial.npy"):
        if os.path.exists(os.path.join(workdir, stale)):
            os.remove(os.path.join(workdir, stale))
    for name in sorted(os.listdir(upload)):
        source = os.path.join(upload, name)
        if os.path.isfile(source) and not os.path.islink(source) and name.endswith(UPLOAD_SUFFIXES):
            shutil.copyfile(source, os.path.join(workdir, name))

    os.environ.setdefault("MPLBACKEND", "Agg")
    if path:
        sys.path.insert(0, path)
    os.chdir(workdir)
    random.seed(args.seed)
    import numpy as np
    np.random.seed(args.seed)
    import rps.robotarium as robotarium_module
    standin_loaded = getattr(sys.modules.get("rps"), "STANDIN", False)
    if standin_loaded != (kind == "standin"):
        raise SystemExit("run_submission: imported %s, expected the %s simulator" %
                         (sys.modules["rps"].__file__, kind))

    recorded = []
    official_class = robotarium_module.Robotarium

    class Checked(official_class):
        """The simulator's own class, watched: its start-up drive gets a step budget (the official
        one can deadlock on packed start poses and would run forever), poses can be recorded."""

        def __init__(self, *a, **kw):
            self._dream_startup_steps = 0
            if args.skip_initialization:
                kw["skip_initialization"] = True
            if args.no_pacing:
                kw["sim_in_real_time"] = False
            super().__init__(*a, **kw)

        def step(self):
            if getattr(self, "initializing", False):
                self._dream_startup_steps += 1
                if self._dream_startup_steps > args.startup_max_steps:
                    raise StartupTimeout(self._dream_startup_steps - 1)
            return super().step()

        def get_poses(self):
            poses = super().get_poses()
            if args.record_poses and not getattr(self, "initializing", False):
                recorded.append(poses.copy())
            return poses

    robotarium_module.Robotarium = Checked

    report = {"simulator": kind, "simulator_path": path or (sys.modules["rps"].__file__ if kind == "official" else ""),
              "ok": False, "error": None, "warnings": [], "debug_text": "", "verdict": "unknown",
              "python": sys.version.split()[0], "numpy": np.__version__}
    started = time.monotonic()
    tee = Tee(sys.stdout if args.echo else None)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            with contextlib.redirect_stdout(tee):
                runpy.run_path(os.path.join(workdir, args.main), run_name="__main__")
            report["ok"] = True
        except StartupTimeout as timeout:
            report["error"] = ("the simulator's start-up drive did not bring the robots onto their start poses "
                               "within %d steps (%.0f s): its barrier certificates deadlock on these start poses, "
                               "and the lab would likely reject the experiment; spread the start poses" %
                               (timeout.steps, timeout.steps * 0.033))
            report["startup_timeout"] = True
        except SystemExit as stop:
            report["error"] = "the script exited: %s" % (stop.code,)
        except BaseException:  # noqa: B902 - report whatever the script raised
            report["error"] = traceback.format_exc()
    report["warnings"] = ["%s:%s: %s: %s" % (w.filename, w.lineno, w.category.__name__, w.message) for w in caught]
    report["wall_s"] = time.monotonic() - started
    output = tee.copy.getvalue()
    # What the lab returns besides the saved files: the script's output.
    with open(os.path.join(workdir, "stdout.txt"), "w", encoding="utf-8") as f:
        f.write(output)
    report["debug_text"] = debug_text(output)
    report["verdict"] = verdict_of(report["debug_text"])
    report["finished_line"] = next((line for line in output.splitlines() if line.startswith("DREAM: finished")), "")
    if args.record_poses:
        np.save(args.record_poses, np.array(recorded))
    with open(args.report, "w", encoding="utf-8") as f:
        json.dump(report, f, indent=2)
        f.write("\n")
    return 0 if report["ok"] else 1


if __name__ == "__main__":
    sys.exit(main())
