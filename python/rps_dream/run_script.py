"""Runs one Robotarium script for `dream run SCRIPT.py`: python3 run_script.py SCRIPT [ARGS...].

The command starts it with this folder first on PYTHONPATH (so `import rps` is DREAM's rps), in
the run folder (DREAM_RUN_DIR: the script's np.save files land there), with the seed of the run
(DREAM_SCRIPT_SEED: Python's `random` and numpy's global stream seeded with it before the script
runs, so a run is repeatable). A call DREAM's rps lacks ends the script with one line naming the
call and the script's line; any other error is the script's own and is shown as Python shows it.
Either way every robot is reported failed to the world, which stops them, and the exit code is 1.
"""

import os
import random
import runpy
import sys
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))


def _script_line(error, script):
    """'SCRIPT:LINE' of the script's innermost frame in `error`'s traceback."""
    where = script
    for frame in traceback.extract_tb(error.__traceback__):
        if os.path.abspath(frame.filename) == script:
            where = f"{script}:{frame.lineno}"
    return where


def _missing_call(error):
    """The text for an error DREAM's rps raised on purpose, or None."""
    from rps.robotarium import NotInDream
    if isinstance(error, NotInDream):
        return str(error)
    if isinstance(error, ImportError) and (error.name or "").startswith("rps"):
        missing = error.name
        text = str(error)
        if text.startswith("cannot import name"):
            missing = f"{error.name}.{text.split(chr(39))[1]}"
        return f"{missing}: DREAM's rps does not provide it (docs/robotarium-scripts.md lists what it does)"
    if isinstance(error, AttributeError) and type(getattr(error, "obj", None)).__module__ == "rps.robotarium":
        return f"Robotarium.{error.name}: DREAM's rps does not provide it (docs/robotarium-scripts.md)"
    return None


def _report_failure(error, script):
    from rps import robotarium
    missing = _missing_call(error)
    if missing is not None:
        detail = f"{_script_line(error, script)}: {missing}"
        print(f"dream run: {detail}", file=sys.stderr)
    else:
        traceback.print_exception(type(error), error, error.__traceback__)
        detail = f"{_script_line(error, script)}: {type(error).__name__}: {error}"
    robot = robotarium.made()
    if robot is not None:
        robot.fail(detail)


class _Tee:
    """The script's prints both in the run folder (this process's stdout) and on the command's terminal."""

    def __init__(self, stream, terminal):
        self._stream, self._terminal = stream, terminal

    def write(self, text):
        self._terminal.write(text)
        return self._stream.write(text)

    def flush(self):
        self._terminal.flush()
        self._stream.flush()

    def __getattr__(self, name):
        return getattr(self._stream, name)


def _tee_to_terminal():
    fd = os.environ.get("DREAM_SCRIPT_TERMINAL_FD", "")
    if fd.isdigit():
        terminal = os.fdopen(int(fd), "w", buffering=1)
        sys.stdout = _Tee(sys.stdout, terminal)
        sys.stderr = _Tee(sys.stderr, terminal)


def main(argv):
    if len(argv) < 2:
        print("usage: run_script.py SCRIPT.py [ARGS...]", file=sys.stderr)
        return 2
    script = os.path.abspath(argv[1])
    _tee_to_terminal()
    try:
        import numpy  # noqa: F401  DREAM's rps, as the official one, is built on it
    except ImportError as missing:
        # Said here, not as a traceback from deep in rps: a newcomer's python3 often lacks it.
        print(f"dream run: {sys.executable} cannot import numpy ({missing}), which rps needs: install it for "
              f"that Python, or name one that has it in DREAM_PYTHON (e.g. DREAM_PYTHON=/usr/bin/python3)",
              file=sys.stderr)
        return 1
    run_dir = os.environ.get("DREAM_RUN_DIR")
    if run_dir:
        os.chdir(run_dir)
    sys.argv = [script] + argv[2:]
    # As `python3 SCRIPT` would have it, with DREAM's rps before the script's folder.
    sys.path[0:1] = [HERE, os.path.dirname(script)]
    seed = os.environ.get("DREAM_SCRIPT_SEED", "")
    if seed:
        import numpy as np
        random.seed(int(seed))
        np.random.seed(int(seed) % (1 << 32))
    try:
        runpy.run_path(script, run_name="__main__")
    except SystemExit as done:
        if done.code not in (None, 0):  # as Python ends it (no traceback); the world is told the robots failed
            from rps import robotarium
            if robotarium.made() is not None:
                robotarium.made().fail(f"{_script_line(done, script)}: the script exited with {done.code!r}")
        raise
    except BaseException as error:  # noqa: B036 - the script's error, whatever it is, is reported
        from rps._world_link import WorldGone
        if isinstance(error, WorldGone):  # --steps, or the world stopped: not the script's fault
            print(f"dream run: {_script_line(error, script)}: {error}", file=sys.stderr)
            return 0
        _report_failure(error, script)
        return 1
    finally:
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
