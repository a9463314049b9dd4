"""DREAM's `rps` for unmodified Robotarium scripts (`dream run SCRIPT.py`, docs/robotarium-scripts.md).

rps.robotarium.Robotarium is the official V2.0.0 class backed by DREAM's world over LCM (this
folder's robotarium.py); everything else (rps.utilities.*, the start-up drive) is the
check-submission stand-in's (bridge/python/standin/rps), which loads DREAM's one Python toolbox
(python/dream/): this package's path is extended with that folder, so there is one implementation.
"""

import os

_HERE = os.path.dirname(os.path.abspath(__file__))
# The stand-in's folder: given by `dream run` (DataFiles::BridgePythonDir), else the source tree's.
_STANDIN = os.path.join(os.environ.get("DREAM_BRIDGE_PYTHON_DIR") or
                        os.path.join(_HERE, "..", "..", "..", "bridge", "python"), "standin", "rps")
STANDIN_DIR = os.path.normpath(_STANDIN)
if not os.path.isfile(os.path.join(STANDIN_DIR, "startup_drive.py")):
    raise ImportError(f"DREAM's rps needs the stand-in's rps folder, not found at {STANDIN_DIR}")
__path__.append(STANDIN_DIR)  # noqa: F821 - a package's own __path__

DREAM = True
