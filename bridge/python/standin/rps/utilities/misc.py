"""Stand-in for rps.utilities.misc: DREAM's python/dream/misc.py, the one Python
implementation (the official functions, arguments and numbers; tests/python/test_toolbox.py)."""

import numpy as np  # noqa: F401  (the official module has it: `import *` scripts use it)

from rps.utilities._dream_toolbox import dream_package

_misc = dream_package().misc
determine_font_size = _misc.determine_font_size
generate_initial_poses = _misc.generate_initial_poses
generate_random_poses = _misc.generate_random_poses
generate_random_positions = _misc.generate_random_positions
create_at_pose = _misc.create_at_pose
create_at_position = _misc.create_at_position
rotation_matrix = _misc.rotation_matrix
unique_filename = _misc.unique_filename
