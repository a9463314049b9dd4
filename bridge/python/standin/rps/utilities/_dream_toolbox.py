"""Where the stand-in's toolbox comes from: DREAM's Python package (python/dream/: the barrier
certificates, controllers, transformations, graph and misc helpers, the one Python implementation
of each), loaded from the source tree (python/dream/) or an installation
(share/dream/python-runtime/dream/) under a private name, so a submission's own `dream` package,
if it has one, is left alone."""

import importlib.util
import os
import sys

_HERE = os.path.dirname(os.path.abspath(__file__))
# bridge/python/standin/rps/utilities -> the source tree's python/dream; share/dream/bridge/standin/
# rps/utilities -> share/dream/python-runtime/dream.
_CANDIDATES = (os.path.join(_HERE, "..", "..", "..", "..", "..", "python", "dream"),
               os.path.join(_HERE, "..", "..", "..", "..", "python-runtime", "dream"))
_PRIVATE_NAME = "_dream_standin_toolbox"


def dream_package():
    """DREAM's `dream` package, loaded once."""
    if _PRIVATE_NAME in sys.modules:
        return sys.modules[_PRIVATE_NAME]
    for candidate in _CANDIDATES:
        folder = os.path.normpath(candidate)
        init = os.path.join(folder, "__init__.py")
        if os.path.isfile(init):
            spec = importlib.util.spec_from_file_location(_PRIVATE_NAME, init, submodule_search_locations=[folder])
            package = importlib.util.module_from_spec(spec)
            sys.modules[_PRIVATE_NAME] = package  # before running it: its relative imports look it up
            try:
                spec.loader.exec_module(package)
            except BaseException:
                del sys.modules[_PRIVATE_NAME]
                raise
            return package
    raise ImportError("the stand-in's toolbox is DREAM's python/dream package, found at none of: " +
                      ", ".join(os.path.normpath(c) for c in _CANDIDATES))
