"""What the bridge's test drivers share (as tests/integration/dreamtest.py for the integration tests):
their failures and skips, the check-submission flags of the simulator they were asked for, and their
ending: the report printed, then PASS, "FAIL: reason" (exit 1) or "SKIP: reason" (exit 77), and the
temporary folder removed, or kept and named with DREAM_TEST_KEEP=1.
"""

import os
import shutil
import subprocess
import tempfile

SKIP = 77


class Failure(Exception):
    pass


class Skipped(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def official_checkout(tmp):
    """$ROBOTARIUM_PYTHON_SIMULATOR as a checkout (a bare git repository's HEAD is checked out in `tmp`);
    None when it is not set."""
    path = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
    if not path:
        return None
    if os.path.isfile(os.path.join(path, "rps", "robotarium.py")):
        return path
    # A bare git repository (a mirror): check out its HEAD.
    target = os.path.join(tmp, "robotarium_python_simulator")
    os.makedirs(target)
    archive = subprocess.run(["git", "-C", path, "archive", "HEAD"], capture_output=True, check=True).stdout
    subprocess.run(["tar", "-x", "-C", target], input=archive, check=True)
    check(os.path.isfile(os.path.join(target, "rps", "robotarium.py")), path + " holds no rps/robotarium.py")
    return target


def simulator_flags(simulator, tmp, purpose):
    """check-submission's flags for --simulator standin|official, and the official checkout (None for the
    stand-in). Skipped, saying `purpose`, when the official simulator is asked for and not there."""
    if simulator == "standin":
        return ["--standin"], None
    checkout = official_checkout(tmp)
    if checkout is None:
        raise Skipped("set ROBOTARIUM_PYTHON_SIMULATOR to a checkout (or bare git repository) of "
                      "robotarium/robotarium_python_simulator " + purpose)
    return ["--require-official", "--simulator", checkout], checkout


def drive(prefix, body):
    """Runs body(tmp, report) in a new temporary folder named `prefix`...: it appends what it found to the
    list `report` and returns the words after PASS ("" for none), or raises Failure or Skipped. Prints the
    report and the ending; returns the driver's exit code (0, 1 or SKIP)."""
    tmp = tempfile.mkdtemp(prefix=prefix)
    report = []
    try:
        passed = body(tmp, report)
        if report:
            print("\n".join(report))
        print("PASS" + (" " + passed if passed else ""))
        return 0
    except Skipped as skipped:
        print("SKIP: %s" % skipped)
        return SKIP
    except Failure as failure:
        if report:
            print("\n".join(report))
        print("FAIL: %s" % failure)
        return 1
    finally:
        if os.environ.get("DREAM_TEST_KEEP") == "1":
            print("kept " + tmp)
        else:
            shutil.rmtree(tmp, ignore_errors=True)
