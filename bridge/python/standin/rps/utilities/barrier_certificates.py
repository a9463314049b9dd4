"""Stand-in for rps.utilities.barrier_certificates: DREAM's one Python implementation of the
Robotarium V2 certificates, python/dream/barriers.py (rps's formulas on cvxopt with rps's
settings, so the commands are the official ones). It needs cvxopt (Debian: python3-cvxopt) when
a certificate is made, as the official package does."""

import numpy as np  # noqa: F401  (the official module has it: `import *` scripts use it)

from rps.utilities._dream_toolbox import dream_package

_barriers = dream_package().barriers


# The stand-in's certificates solve as rps does bit for bit (bit_exact), so its start-up drive and
# an exported script's barrier equal the official simulator's exactly.
def create_uni_barrier_certificate(*args, **kwargs):
    return _barriers.create_uni_barrier_certificate(*args, bit_exact=True, **kwargs)


def create_uni_barrier_certificate_with_boundary(*args, **kwargs):
    return _barriers.create_uni_barrier_certificate_with_boundary(*args, bit_exact=True, **kwargs)


def create_si_barrier_certificate(*args, **kwargs):
    return _barriers.create_si_barrier_certificate(*args, bit_exact=True, **kwargs)


def create_si_barrier_certificate_with_boundary(*args, **kwargs):
    return _barriers.create_si_barrier_certificate_with_boundary(*args, bit_exact=True, **kwargs)


def _solve_qp(N, vhat, A, b):
    """rps's private helper, which examples import (sensors/distance_sensor_avoidance.py):
    min |v - vhat|^2 s.t. A v <= b for N robots' velocities (2 x N), None when cvxopt fails."""
    return _barriers._solve_qp(np.reshape(np.asarray(vhat, dtype=float), (2, N), order="F"),
                               np.asarray(A, dtype=float), np.asarray(b, dtype=float))
