"""Stand-in for rps.utilities.transformations: DREAM's python/dream/transformations.py, the one Python
implementation (the official functions, arguments and numbers; tests/python/test_toolbox.py)."""

import numpy as np  # noqa: F401  (the official module has it: `import *` scripts use it)

from rps.utilities._dream_toolbox import dream_package

_transformations = dream_package().transformations
create_si_to_uni_dynamics = _transformations.create_si_to_uni_dynamics
create_si_to_uni_dynamics_with_backwards_motion = _transformations.create_si_to_uni_dynamics_with_backwards_motion
create_si_to_uni_mapping = _transformations.create_si_to_uni_mapping
create_uni_to_si_mapping = _transformations.create_uni_to_si_mapping
