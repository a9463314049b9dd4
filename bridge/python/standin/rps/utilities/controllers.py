"""Stand-in for rps.utilities.controllers: DREAM's python/dream/controllers.py, the one Python
implementation (the official functions, arguments and numbers; tests/python/test_toolbox.py)."""

import numpy as np  # noqa: F401  (the official module has it: `import *` scripts use it)

from rps.utilities._dream_toolbox import dream_package

_controllers = dream_package().controllers
create_si_position_controller = _controllers.create_si_position_controller
create_uni_position_controller = _controllers.create_uni_position_controller
create_pose_controller_clf = _controllers.create_pose_controller_clf
create_pose_controller_hybrid = _controllers.create_pose_controller_hybrid
create_pose_parking_controller_clf = _controllers.create_pose_parking_controller_clf
create_pose_parking_controller_hybrid = _controllers.create_pose_parking_controller_hybrid
