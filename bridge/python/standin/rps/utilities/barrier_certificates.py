"""Stand-in for rps.utilities.barrier_certificates (the unicycle barriers, with and without boundary).

The same constraints as the V2.0.0 certificate (pairwise barrier h = |d|^2 - r^2
with rate gain * h^3, four wall barriers with 0.4 * gain, an octagon speed
limit, all on the points `projection_distance` ahead of the robots), but the
quadratic program min |u - u_nominal|^2 s.t. A u <= b is solved to 1e-10 by
Hildreth's dual coordinate ascent in numpy, where the official simulator asks
cvxopt for a 1e-2 relative tolerance: results agree where no constraint is
active and differ by the official solver's slack where one is.
"""

import math
import warnings

import numpy as np


def _project(u_nominal, a, b, sweeps=2000, tolerance=1e-10):
    """min |u - u_nominal|^2 subject to a u <= b; None if it does not converge (infeasible)."""
    u = u_nominal.copy()
    lam = np.zeros(a.shape[0])
    norms = np.einsum("ij,ij->i", a, a)
    active = norms > 0
    for _ in range(sweeps):
        worst = 0.0
        for i in np.flatnonzero(active):
            slack = a[i] @ u - b[i]
            step = max(-lam[i], slack / norms[i])
            if step != 0.0:
                lam[i] += step
                u -= step * a[i]
            worst = max(worst, slack)
        if worst <= tolerance:
            return u
    return None


def create_uni_barrier_certificate(barrier_gain=100.0, safety_radius=0.15, projection_distance=0.05,
                                   velocity_magnitude_limit=0.2):
    """Without walls; as in V2.0.0 the octagon's first side is bounded by the limit itself."""
    return _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, None,
                     "create_uni_barrier_certificate")


def create_uni_barrier_certificate_with_boundary(safety_radius=0.12, barrier_gain=150.0, projection_distance=0.03,
                                                 velocity_magnitude_limit=0.2, boundary_points=None):
    bounds = np.array([-1.6, 1.6, -1.0, 1.0]) if boundary_points is None else np.asarray(boundary_points, float)
    return _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, bounds,
                     "create_uni_barrier_certificate_with_boundary")


def _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, bounds, name):
    radius = safety_radius + 2 * projection_distance
    limit = velocity_magnitude_limit * math.cos(math.pi / 8)
    c = 1 / math.sqrt(2)
    octagon = np.array([[1, 0], [c, c], [0, 1], [-c, c], [-1, 0], [-c, -c], [0, -1], [c, -c]])

    def certificate(dxu, x, obstacles=None):
        n = dxu.shape[1]
        if n < 2:
            return dxu
        cos_t, sin_t = np.cos(x[2, :]), np.sin(x[2, :])
        points = x[:2, :] + projection_distance * np.vstack([cos_t, sin_t])
        dxi = np.vstack([dxu[0, :] * cos_t - projection_distance * dxu[1, :] * sin_t,
                         dxu[0, :] * sin_t + projection_distance * dxu[1, :] * cos_t])
        if obstacles is not None and obstacles.size > 0:
            points = np.hstack([points, obstacles])
            dxi = np.hstack([dxi, np.zeros((2, obstacles.shape[1]))])
        m = points.shape[1]
        rows, rhs = [], []
        for i in range(m - 1):
            for j in range(i + 1, m):
                d = points[:, i] - points[:, j]
                h = d @ d - radius ** 2
                row = np.zeros(2 * m)
                row[2 * i:2 * i + 2] = -2 * d
                row[2 * j:2 * j + 2] = 2 * d
                rows.append(row)
                rhs.append(barrier_gain * h ** 3)
        for k in range(m):
            px, py = points[:, k]
            walls = () if bounds is None else (
                ((0, 1), bounds[3] - radius / 2 - py), ((0, -1), py - bounds[2] - radius / 2),
                ((1, 0), bounds[1] - radius / 2 - px), ((-1, 0), px - bounds[0] - radius / 2))
            for direction, gap in walls:
                row = np.zeros(2 * m)
                row[2 * k:2 * k + 2] = direction
                rows.append(row)
                rhs.append(0.4 * barrier_gain * gap ** 3)
            for index, side in enumerate(octagon):
                row = np.zeros(2 * m)
                row[2 * k:2 * k + 2] = side
                rows.append(row)
                rhs.append(velocity_magnitude_limit if (index == 0 and bounds is None) else limit)
        safe = _project(dxi.reshape(-1, order="F"), np.array(rows), np.array(rhs))
        if safe is None:
            warnings.warn(name + ": Safety QP failed. Commanding zero velocities.")
            return np.zeros((2, n))
        safe = safe.reshape((2, m), order="F")[:, :n]
        return np.vstack([cos_t * safe[0] + sin_t * safe[1],
                          (-sin_t * safe[0] + cos_t * safe[1]) / projection_distance])

    return certificate
