"""Stand-in for rps.utilities.barrier_certificates: DREAM's one Python implementation of the
Robotarium V2 certificates, python/dream/barriers.py (rps's formulas on cvxopt with rps's
settings, so the commands are the official ones), loaded from where DREAM keeps it: the source
tree (python/dream/) or an installation (share/dream/python-runtime/dream/). It needs cvxopt
(Debian: python3-cvxopt) when a certificate is made, as the official package does."""

import importlib.util
import os

_HERE = os.path.dirname(os.path.abspath(__file__))
# bridge/python/standin/rps/utilities -> the source tree's python/dream; share/dream/bridge/standin/
# rps/utilities -> share/dream/python-runtime/dream.
_CANDIDATES = (os.path.join(_HERE, "..", "..", "..", "..", "..", "python", "dream", "barriers.py"),
               os.path.join(_HERE, "..", "..", "..", "..", "python-runtime", "dream", "barriers.py"))


def _load_dream_barriers():
    for candidate in _CANDIDATES:
        path = os.path.normpath(candidate)
        if os.path.isfile(path):
            # A private module name: the submission may have a `dream` package of its own.
            spec = importlib.util.spec_from_file_location("_dream_standin_barriers", path)
            module = importlib.util.module_from_spec(spec)
            spec.loader.exec_module(module)
            return module
    raise ImportError("the stand-in's barrier certificates are DREAM's python/dream/barriers.py, found at none of: " +
                      ", ".join(os.path.normpath(c) for c in _CANDIDATES))


_barriers = _load_dream_barriers()
create_uni_barrier_certificate = _barriers.create_uni_barrier_certificate
create_uni_barrier_certificate_with_boundary = _barriers.create_uni_barrier_certificate_with_boundary
create_si_barrier_certificate = _barriers.create_si_barrier_certificate
create_si_barrier_certificate_with_boundary = _barriers.create_si_barrier_certificate_with_boundary
