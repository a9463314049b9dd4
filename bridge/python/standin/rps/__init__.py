"""DREAM's stand-in for the Robotarium Python package (rps), V2 semantics.

Not the official simulator: a small re-implementation, written for this
project from the Robotarium's documented behaviour (docs/robotarium.md), so
that CI can run an exported submission without the official package (which
needs matplotlib). It offers what DREAM's exported scripts use: rps.robotarium.Robotarium
(constructor, get_poses, set_velocities, step, debug, the physical constants)
and rps.utilities.barrier_certificates (the unicycle and single-integrator certificates).
Needs numpy, and cvxopt for the barrier certificates (the start-up drive uses one): they are
DREAM's python/dream/barriers.py, the one Python implementation.
"""

STANDIN = True
