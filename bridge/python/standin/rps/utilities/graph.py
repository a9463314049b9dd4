"""Stand-in for rps.utilities.graph: DREAM's python/dream/graph.py, the one Python
implementation (the official functions, arguments and numbers; tests/python/test_toolbox.py)."""

import numpy as np  # noqa: F401  (the official module has it: `import *` scripts use it)

from rps.utilities._dream_toolbox import dream_package

_graph = dream_package().graph
completeGL = _graph.completeGL
cycleGL = _graph.cycleGL
lineGL = _graph.lineGL
random_connectedGL = _graph.random_connectedGL
randomGL = _graph.randomGL
delta_disk_neighbors = _graph.delta_disk_neighbors
topological_neighbors = _graph.topological_neighbors
