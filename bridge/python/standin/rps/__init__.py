"""DREAM's stand-in for the Robotarium Python package (rps), V2 semantics.

Not the official simulator: a small re-implementation, written for this
project from the Robotarium's documented behaviour (docs/robotarium.md), so
that CI can run an exported submission without the official package (which
needs matplotlib and cvxopt). It offers what DREAM's exported scripts use: rps.robotarium.Robotarium
(constructor, get_poses, set_velocities, step, debug, the physical constants)
and rps.utilities.barrier_certificates.create_uni_barrier_certificate[_with_boundary].
Needs only numpy.
"""

STANDIN = True
