#!/usr/bin/python3
"""How far the exact optimum of the barrier certificates' QP is from the commands rps gives.

Usage:
    /usr/bin/python3 barrier_exact_gap.py <robotarium_python_simulator checkout> [cases]

rps asks cvxopt for a relative gap and feasibility of 1e-2 (at most 50 iterations), so its
commands are an early interior-point iterate. Any solver that solves the QP exactly (COIN-OR Clp,
Ipopt, OSQP, qpOASES, or cvxopt itself at 1e-12) lands on the optimum instead. This prints the
distance between the two on random 2-20 robot states, for create_uni_barrier_certificate_with_boundary():
the reason dream::barriers reproduces cvxopt's iteration rather than calling a packaged QP solver
(docs/dependencies.md#the-barrier-certificates-qp).
"""

import sys
import warnings

import numpy as np


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    sys.path.insert(0, sys.argv[1])
    cases = int(sys.argv[2]) if len(sys.argv) > 2 else 300
    from rps.utilities import barrier_certificates as bc
    from cvxopt import solvers
    warnings.simplefilter("ignore")
    rng = np.random.default_rng(1)
    gaps = []
    for _ in range(cases):
        n = int(rng.integers(2, 21))
        x = np.vstack([rng.uniform(-1.5, 1.5, n), rng.uniform(-0.9, 0.9, n), rng.uniform(-np.pi, np.pi, n)])
        dxu = np.vstack([rng.uniform(-0.2, 0.2, n), rng.uniform(-3, 3, n)])
        official = bc.create_uni_barrier_certificate_with_boundary()(dxu, x)
        saved = dict(solvers.options)
        solvers.options.update({"reltol": 1e-12, "feastol": 1e-12, "abstol": 1e-12, "maxiters": 200})
        exact = bc.create_uni_barrier_certificate_with_boundary()(dxu, x)
        solvers.options.clear()
        solvers.options.update(saved)
        if not official.any() or not exact.any():
            continue  # a QP that failed in either: zeros, not a tolerance
        gaps.append(np.abs(official - exact).max())
    gaps = np.array(gaps)
    print("%d states; |rps - exact optimum| of (v, w): median %.3g, 90th percentile %.3g, max %.3g; "
          "over 1e-5 in %.0f%% of states" % (len(gaps), np.median(gaps), np.percentile(gaps, 90), gaps.max(),
                                             100.0 * np.mean(gaps > 1e-5)))


if __name__ == "__main__":
    main()
