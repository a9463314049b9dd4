"""The Robotarium V2 barrier certificates (rps/utilities/barrier_certificates.py), the same
numbers on the same solver: cvxopt's QP with rps's settings (reltol and feastol 1e-2, at most 50
iterations), so a command agrees with the official simulator's and the lab's. The C++ twin,
dream::barriers (agents/barriers/), iterates as cvxopt does and agrees to ~1e-11
(tests/data/robotarium_v2_barriers.json; docs/python-controllers.md#barrier-certificates).

    barrier = dream.create_uni_barrier_certificate_with_boundary()   # dream re-exports all four
    dxu = barrier(dxu, poses)          # 2 x N commands, 3 x N poses, all robots at once

A certificate is one quadratic program over every robot: it needs every robot's wanted command.
A run config's `barriers:` section with `apply_in: world` has the simulator (and the exported
script) apply it to all commands each step; call these yourself when one controller drives every
robot, or to see what the world will make of a command. Needs numpy and cvxopt (Debian:
python3-cvxopt; pip: cvxopt), imported only when a certificate is made."""

import math
import warnings

import numpy as np

# rps's cvxopt settings, passed to each call (rps sets them globally for every cvxopt user).
QP_OPTIONS = {"show_progress": False, "reltol": 1e-2, "feastol": 1e-2, "maxiters": 50}
# The boundaries rps's certificates default to: the arena for the unicycle one, 0.1 m beyond it
# for the single-integrator one (as rps has it).
UNICYCLE_BOUNDARY = (-1.6, 1.6, -1.0, 1.0)
SINGLE_INTEGRATOR_BOUNDARY = (-1.7, 1.7, -1.1, 1.1)
# Debian and pip spell the one package the same.
_CVXOPT_MISSING = ("dream.barriers needs cvxopt, which this Python cannot import (Debian: apt-get install "
                   "python3-cvxopt; pip install cvxopt)")


def _cvxopt():
    try:
        import cvxopt
        import cvxopt.solvers
    except ImportError as error:
        raise ImportError(_CVXOPT_MISSING) from error
    return cvxopt


def _positive(name, value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise ValueError("%s must be a positive number, got %r" % (name, value))
    return float(value)


def _boundary(points, default):
    if points is None:
        return np.array(default, dtype=float)
    b = np.asarray(points, dtype=float).reshape(-1)
    if b.shape != (4,) or not np.all(np.isfinite(b)) or not (b[0] < b[1] and b[2] < b[3]):
        raise ValueError("boundary_points must be [x_min, x_max, y_min, y_max] with x_min < x_max and "
                         "y_min < y_max, got %r" % (points,))
    return b


def _columns(name, array, rows):
    a = np.asarray(array, dtype=float)
    if a.ndim != 2 or a.shape[0] != rows:
        raise ValueError("%s must be %d x N, got shape %s" % (name, rows, a.shape))
    return a


def _solve_qp(vhat, A, b):
    """min |v - vhat|^2 s.t. A v <= b as rps builds and solves it; None when cvxopt does not end
    'optimal' (rps then commands zeros)."""
    cvxopt = _cvxopt()
    n = vhat.shape[1]
    H = cvxopt.sparse(cvxopt.matrix(2.0 * np.eye(2 * n)))
    f = cvxopt.matrix(-2.0 * vhat.reshape(-1, order="F"))
    try:
        solution = cvxopt.solvers.qp(H, f, cvxopt.matrix(A), cvxopt.matrix(b), options=dict(QP_OPTIONS))
    except (ArithmeticError, ValueError, ZeroDivisionError):
        return None
    if solution["status"] != "optimal":
        return None
    return np.reshape(np.array(solution["x"]), (2, n), order="F")


def _pair_rows(x, safety_radius, barrier_gain, A, b):
    n = x.shape[1]
    row = 0
    for i in range(n - 1):
        for j in range(i + 1, n):
            diff = x[:, i] - x[:, j]
            h = np.dot(diff, diff) - safety_radius ** 2
            A[row, 2 * i:2 * i + 2] = -2 * diff
            A[row, 2 * j:2 * j + 2] = 2 * diff
            b[row] = barrier_gain * (h ** 3)
            row += 1
    return row


def _wall_rows(x, safety_radius, barrier_gain, bp, A, b, row):
    for k in range(x.shape[1]):
        columns = slice(2 * k, 2 * k + 2)
        walls = (([0, 1], bp[3] - safety_radius / 2 - x[1, k]), ([0, -1], x[1, k] - bp[2] - safety_radius / 2),
                 ([1, 0], bp[1] - safety_radius / 2 - x[0, k]), ([-1, 0], x[0, k] - bp[0] - safety_radius / 2))
        for side, gap in walls:
            A[row, columns] = side
            b[row] = 0.4 * barrier_gain * gap ** 3
            row += 1
    return row


def _octagon_rows(n, magnitude_limit, first_side_unscaled, A, b, row):
    """The speed octagon, 8 sides per robot in rps's order; rps's certificate without boundary
    bounds the first side by the limit itself, the others by limit * cos(pi/8)."""
    d = 1 / np.sqrt(2)
    sides = ([1, 0], [d, d], [0, 1], [-d, d], [-1, 0], [-d, -d], [0, -1], [d, -d])
    for k in range(n):
        for index, side in enumerate(sides):
            A[row, 2 * k:2 * k + 2] = side
            scaled = magnitude_limit * np.cos(np.pi / 8)
            b[row] = magnitude_limit if (index == 0 and first_side_unscaled) else scaled
            row += 1
    return row


def _single_integrator(safety_radius, barrier_gain, magnitude_limit, boundary, name):
    _cvxopt()  # fail at creation, naming the package, rather than at the first step
    safety_radius = _positive("safety_radius", safety_radius)
    barrier_gain = _positive("barrier_gain", barrier_gain)
    magnitude_limit = _positive("magnitude_limit", magnitude_limit)

    def barrier_certificate(dxi, x):
        dxi = _columns("dxi", dxi, 2)
        x = np.asarray(x, dtype=float)
        if x.ndim != 2 or x.shape[0] < 2:
            raise ValueError("x must be 2 x N (or 3 x N poses), got shape %s" % (x.shape,))
        x = x[:2, :]
        n = dxi.shape[1]
        if x.shape[1] != n:
            raise ValueError("dxi has %d columns, x %d" % (n, x.shape[1]))
        if n < 2:
            return dxi
        rows = math.comb(n, 2) + (4 * n if boundary is not None else 0) + 8 * n
        A = np.zeros((rows, 2 * n))
        b = np.zeros(rows)
        row = _pair_rows(x, safety_radius, barrier_gain, A, b)
        if boundary is not None:
            row = _wall_rows(x, safety_radius, barrier_gain, boundary, A, b, row)
        _octagon_rows(n, magnitude_limit, boundary is None, A, b, row)
        v = _solve_qp(np.copy(dxi), A, b)
        if v is None:
            warnings.warn("%s: QP failed. Commanding zero velocities." % name)
            return np.zeros((2, n))
        return v

    return barrier_certificate


def create_si_barrier_certificate(safety_radius=0.15, barrier_gain=100.0, magnitude_limit=0.2):
    """rps's single-integrator certificate without boundary: f(dxi, x) -> safe dxi (2 x N)."""
    return _single_integrator(safety_radius, barrier_gain, magnitude_limit, None, "create_si_barrier_certificate")


def create_si_barrier_certificate_with_boundary(safety_radius=0.15, barrier_gain=100.0, magnitude_limit=0.2,
                                                boundary_points=None):
    """rps's single-integrator certificate with the walls of `boundary_points`
    ([x_min, x_max, y_min, y_max]; default [-1.7, 1.7, -1.1, 1.1] as in rps)."""
    return _single_integrator(safety_radius, barrier_gain, magnitude_limit,
                              _boundary(boundary_points, SINGLE_INTEGRATOR_BOUNDARY),
                              "create_si_barrier_certificate_with_boundary")


def _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, boundary, name):
    d = _positive("projection_distance", projection_distance)
    si = _single_integrator(_positive("safety_radius", safety_radius) + 2 * d, barrier_gain, velocity_magnitude_limit,
                            boundary, name)
    si_to_uni_T = np.array([[1, 0], [0, 1 / d]])
    uni_to_si_T = np.array([[1, 0], [0, d]])

    def barrier_unicycle(dxu, x, obstacles=None):
        dxu = _columns("dxu", dxu, 2)
        x = _columns("x", x, 3)
        n = dxu.shape[1]
        if x.shape[1] != n:
            raise ValueError("dxu has %d columns, x %d" % (n, x.shape[1]))
        if n < 2:
            return dxu
        # The point d ahead of each robot, and its velocity: R(theta) diag(1, d) (v, w).
        xi = x[0:2, :] + d * np.array([np.cos(x[2, :]), np.sin(x[2, :])])
        dxi = np.zeros((2, n))
        for i in range(n):
            h = x[2, i]
            R = np.array([[np.cos(h), -np.sin(h)], [np.sin(h), np.cos(h)]])
            dxi[:, i] = R @ uni_to_si_T @ dxu[:, i]
        if obstacles is not None and np.size(obstacles) > 0:
            obstacles = _columns("obstacles", obstacles, 2)
            xi = np.hstack((xi, obstacles))
            dxi = np.hstack((dxi, np.zeros((2, obstacles.shape[1]))))
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            safe = si(dxi, xi)
            failed = any("QP failed" in str(w.message) for w in caught)
        if failed:
            warnings.warn("%s: Safety QP failed. Commanding zero velocities." % name)
            return np.zeros((2, n))
        out = np.zeros((2, n))
        for i in range(n):
            h = x[2, i]
            R = np.array([[np.cos(h), np.sin(h)], [-np.sin(h), np.cos(h)]])
            out[:, i] = si_to_uni_T @ R @ safe[:, i]
        return out

    return barrier_unicycle


def create_uni_barrier_certificate(barrier_gain=100.0, safety_radius=0.15, projection_distance=0.05,
                                   velocity_magnitude_limit=0.2):
    """rps's unicycle certificate without boundary (the one Robotarium.initialize() drives the
    robots onto their start poses with): f(dxu, x) -> safe dxu."""
    return _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, None,
                     "create_uni_barrier_certificate")


def create_uni_barrier_certificate_with_boundary(safety_radius=0.12, barrier_gain=150.0, projection_distance=0.03,
                                                 velocity_magnitude_limit=0.2, boundary_points=None):
    """rps's unicycle certificate with boundary (the examples' and most scripts'):
    f(dxu, x, obstacles=None) -> safe dxu; `obstacles` are 2 x M points kept clear of."""
    return _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit,
                     _boundary(boundary_points, UNICYCLE_BOUNDARY), "create_uni_barrier_certificate_with_boundary")
