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
# From this many robots cvxopt's KKT step goes through _StructuredKkt (the same iterates, answers
# within ~1e-11 of rps's). A certificate made with bit_exact=True keeps rps's dense step for every
# size, bit for bit (the check-submission stand-in's are, so its start-up drive is the official one).
STRUCTURED_KKT_FROM_ROBOTS = 10
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


def _solve_qp(vhat, A, b, bit_exact):
    """min |v - vhat|^2 s.t. A v <= b as rps builds and solves it; None when cvxopt does not end
    'optimal' (rps then commands zeros). cvxopt iterates as in rps; only its linear algebra is
    ours (_StructuredKkt), which is why a 20-robot step takes about 2 ms instead of 15."""
    cvxopt = _cvxopt()
    n = vhat.shape[1]
    H = cvxopt.spmatrix(2.0, range(2 * n), range(2 * n))
    f = cvxopt.matrix(-2.0 * vhat.reshape(-1, order="F"))
    kkt = _StructuredKkt(A, structured=not bit_exact)
    # A few entries per row: sparse, cvxopt's own products with G are cheap too; below
    # STRUCTURED_KKT_FROM_ROBOTS dense, exactly as rps hands it over (setting up the sparse one costs more).
    G = cvxopt.spmatrix(kkt.entries, kkt.rows, kkt.columns, A.shape) if kkt.usable else cvxopt.matrix(A)
    try:
        solution = cvxopt.solvers.qp(H, f, G, cvxopt.matrix(b),
                                     kktsolver=kkt.factor if kkt.usable else None, options=dict(QP_OPTIONS))
    except (ArithmeticError, ValueError, ZeroDivisionError):
        return None
    if solution["status"] != "optimal":
        return None
    return np.reshape(np.array(solution["x"]), (2, n), order="F")


class _StructuredKkt:
    """cvxopt's KKT step for these QPs, solved through their structure. Each row of A touches at
    most two robots' 2-column blocks (a pair, a wall or an octagon side), and the objective is
    |v|^2, so the reduced matrix 2 I + A' W^-2 A is assembled from 2 x 2 outer products instead of a
    dense product (numpy on reference BLAS, as on Debian and the lab, spends ~1 ms on that per
    iteration for 20 robots). The iterates are cvxopt's; the answers agree with rps's to ~1e-11
    (tests/python/test_barriers.py)."""

    def __init__(self, A, structured=True):
        self.rows, self.columns = np.nonzero(A)  # A's few entries, for products without a dense BLAS call
        self.entries = A[self.rows, self.columns]
        rows, columns = A.shape
        self.size = columns
        self.row_count = rows
        blocks = A.reshape(rows, columns // 2, 2) if columns % 2 == 0 else None
        touched = np.any(blocks != 0, axis=2) if blocks is not None else None
        # Below ~10 robots cvxopt's own dense step is as fast (tests/benchmarks/python_barrier_benchmark.py).
        self.usable = (structured and columns >= 2 * STRUCTURED_KKT_FROM_ROBOTS
                       and blocks is not None
                       and bool(np.all(touched.sum(axis=1) <= 2)))
        if not self.usable:
            return
        robots = columns // 2
        first = np.argmax(touched, axis=1)
        last = robots - 1 - np.argmax(touched[:, ::-1], axis=1)
        every = np.arange(rows)
        u = blocks[every, first]
        v = np.where((first != last)[:, None], blocks[every, last], 0.0)
        r = np.array([0, 0, 1, 1])
        c = np.array([0, 1, 0, 1])

        def outer(p, q):
            return (p[:, :, None] * q[:, None, :]).reshape(rows, 4)

        def flat(i, j):  # where each outer product's four entries go in the 2n x 2n matrix
            return (2 * i[:, None] + r) * columns + (2 * j[:, None] + c)

        # Per row: uu', vv', uv', vu' and their places; a factoring only weights and sums them.
        self.products = np.concatenate((outer(u, u), outer(v, v), outer(u, v), outer(v, u)), axis=1)
        self.places = np.concatenate((flat(first, first), flat(last, last), flat(first, last), flat(last, first)),
                                     axis=1).reshape(-1)

    def _times(self, u):
        return np.bincount(self.rows, self.entries * u[self.columns], minlength=self.row_count)

    def _transposed_times(self, y):
        return np.bincount(self.columns, self.entries * y[self.rows], minlength=self.size)

    def factor(self, W):
        cvxopt = _cvxopt()
        d = np.array(W["d"]).reshape(-1)
        weights = 1.0 / (d * d)
        M = np.bincount(self.places, (self.products * weights[:, None]).reshape(-1),
                        minlength=self.size * self.size).reshape(self.size, self.size)
        M[np.diag_indices(self.size)] += 2.0
        factored = cvxopt.matrix(M)
        # 2 I plus a PSD sum fails only on non-finite input, with the ArithmeticError cvxopt expects.
        cvxopt.lapack.potrf(factored)

        def solve(x, y, z):
            bz = np.array(z).reshape(-1)
            rhs = cvxopt.matrix(np.array(x).reshape(-1) + self._transposed_times(weights * bz))
            cvxopt.lapack.potrs(factored, rhs)
            x[:] = rhs
            z[:] = cvxopt.matrix((self._times(np.array(rhs).reshape(-1)) - bz) / d)

        return solve


def _pair_rows(x, safety_radius, barrier_gain, A, b):
    """One row per pair i < j in rps's order (i outer, j inner)."""
    first, second = np.triu_indices(x.shape[1], k=1)
    diff = x[:, first] - x[:, second]
    h = diff[0] * diff[0] + diff[1] * diff[1] - safety_radius ** 2
    rows = np.arange(first.size)
    for axis in (0, 1):
        A[rows, 2 * first + axis] = -2 * diff[axis]
        A[rows, 2 * second + axis] = 2 * diff[axis]
    b[rows] = barrier_gain * (h ** 3)
    return first.size


def _wall_rows(x, safety_radius, barrier_gain, bp, A, b, row):
    """Four rows per robot in rps's order: top, bottom, right, left."""
    n = x.shape[1]
    robots = np.arange(n)
    gaps = (bp[3] - safety_radius / 2 - x[1], x[1] - bp[2] - safety_radius / 2,
            bp[1] - safety_radius / 2 - x[0], x[0] - bp[0] - safety_radius / 2)
    sides = ((1, 1.0), (1, -1.0), (0, 1.0), (0, -1.0))  # (axis, sign) of each wall's row
    for k, ((axis, sign), gap) in enumerate(zip(sides, gaps)):
        rows = row + 4 * robots + k
        A[rows, 2 * robots + axis] = sign
        b[rows] = 0.4 * barrier_gain * gap ** 3
    return row + 4 * n


def _octagon_rows(n, magnitude_limit, first_side_unscaled, A, b, row):
    """The speed octagon, 8 sides per robot in rps's order; rps's certificate without boundary
    bounds the first side by the limit itself, the others by limit * cos(pi/8)."""
    d = 1 / np.sqrt(2)
    sides = np.array([[1, 0], [d, d], [0, 1], [-d, d], [-1, 0], [-d, -d], [0, -1], [d, -d]])
    bounds = np.full(8, magnitude_limit * np.cos(np.pi / 8))
    if first_side_unscaled:
        bounds[0] = magnitude_limit
    robots = np.arange(n)
    for k in range(8):
        rows = row + 8 * robots + k
        A[rows, 2 * robots] = sides[k, 0]
        A[rows, 2 * robots + 1] = sides[k, 1]
        b[rows] = bounds[k]
    return row + 8 * n


def _single_integrator(safety_radius, barrier_gain, magnitude_limit, boundary, name, bit_exact):
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
        v = _solve_qp(np.copy(dxi), A, b, bit_exact)
        if v is None:
            warnings.warn("%s: QP failed. Commanding zero velocities." % name)
            return np.zeros((2, n))
        return v

    return barrier_certificate


def create_si_barrier_certificate(safety_radius=0.15, barrier_gain=100.0, magnitude_limit=0.2, *, bit_exact=False):
    """rps's single-integrator certificate without boundary: f(dxi, x) -> safe dxi (2 x N).
    bit_exact=True (every factory here has it): rps's own dense KKT step at every size, so the
    commands are rps's bit for bit; otherwise within ~1e-11 and faster from 10 robots."""
    return _single_integrator(safety_radius, barrier_gain, magnitude_limit, None, "create_si_barrier_certificate",
                              bit_exact)


def create_si_barrier_certificate_with_boundary(safety_radius=0.15, barrier_gain=100.0, magnitude_limit=0.2,
                                                boundary_points=None, *, bit_exact=False):
    """rps's single-integrator certificate with the walls of `boundary_points`
    ([x_min, x_max, y_min, y_max]; default [-1.7, 1.7, -1.1, 1.1] as in rps)."""
    return _single_integrator(safety_radius, barrier_gain, magnitude_limit,
                              _boundary(boundary_points, SINGLE_INTEGRATOR_BOUNDARY),
                              "create_si_barrier_certificate_with_boundary", bit_exact)


def _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, boundary, name, bit_exact):
    d = _positive("projection_distance", projection_distance)
    si = _single_integrator(_positive("safety_radius", safety_radius) + 2 * d, barrier_gain, velocity_magnitude_limit,
                            boundary, name, bit_exact)

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
        cos, sin = np.cos(x[2, :]), np.sin(x[2, :])
        # Rounded as rps's R @ T @ dxu rounds (matmul sums from +0.0), so the certificate is rps's bit for bit.
        dxi = np.array([0.0 + cos * dxu[0, :] + (-sin * d) * dxu[1, :], 0.0 + sin * dxu[0, :] + (cos * d) * dxu[1, :]])
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
        # Back through R(theta)' and diag(1, 1/d).
        safe = safe[:, :n]
        # As rps's T @ R @ safe: the second row (1/d) * (-sin, cos).
        return np.array([0.0 + cos * safe[0] + sin * safe[1], 0.0 + ((1 / d) * -sin) * safe[0] + ((1 / d) * cos) * safe[1]])

    return barrier_unicycle


def create_uni_barrier_certificate(barrier_gain=100.0, safety_radius=0.15, projection_distance=0.05,
                                   velocity_magnitude_limit=0.2, *, bit_exact=False):
    """rps's unicycle certificate without boundary (the one Robotarium.initialize() drives the
    robots onto their start poses with): f(dxu, x) -> safe dxu."""
    return _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit, None,
                     "create_uni_barrier_certificate", bit_exact)


def create_uni_barrier_certificate_with_boundary(safety_radius=0.12, barrier_gain=150.0, projection_distance=0.03,
                                                 velocity_magnitude_limit=0.2, boundary_points=None, *,
                                                 bit_exact=False):
    """rps's unicycle certificate with boundary (the examples' and most scripts'):
    f(dxu, x, obstacles=None) -> safe dxu; `obstacles` are 2 x M points kept clear of."""
    return _unicycle(safety_radius, barrier_gain, projection_distance, velocity_magnitude_limit,
                     _boundary(boundary_points, UNICYCLE_BOUNDARY), "create_uni_barrier_certificate_with_boundary",
                     bit_exact)
