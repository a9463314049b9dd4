"""What the Python runtime's unit tests start with: numpy, or the test is skipped (exit 77, ctest's
SKIP_RETURN_CODE); the source tree with its python/ first on the path; and, for the tests that
decode messages, lcm-gen's Python types of the build."""

import os
import sys

SKIPPED = 77
SOURCE_DIR = os.path.abspath(os.environ.get("DREAM_SOURCE_DIR",
                                            os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")))


def require_numpy():
    """Skips the test when numpy is missing (Debian: python3-numpy)."""
    require_modules("numpy")


def require_modules(*names):
    """Skips the test when one of the modules `names` is missing, naming it and the Debian
    packages of them all (python3-<name>)."""
    for name in names:
        try:
            __import__(name)
        except ImportError as error:
            packages = " ".join("python3-" + n for n in names)
            print(f"skipped: {error} (Debian: apt-get install {packages})")
            sys.exit(SKIPPED)


def put_runtime_on_path():
    """The source tree's python/ (the dream package) first on sys.path."""
    runtime = os.path.join(SOURCE_DIR, "python")
    if runtime not in sys.path:
        sys.path.insert(0, runtime)


def types_dir(needed="robot_poses_t"):
    """lcm-gen's Python types of the build (DREAM_BUILD_DIR/python), holding `needed`; else skipped."""
    directory = os.path.join(os.environ.get("DREAM_BUILD_DIR", os.path.join(SOURCE_DIR, "build")), "python")
    if not os.path.isfile(os.path.join(directory, "dream", needed + ".py")):
        print(f"lcm-gen's Python types ({needed}) are not in {directory}: skipped")
        sys.exit(SKIPPED)
    return directory
