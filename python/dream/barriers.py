"""The Robotarium V2 barrier certificates (rps/utilities/barrier_certificates.py), the same
numbers as rps's cvxopt QP with rps's settings (reltol and feastol 1e-2, at most 50 iterations):
cvxopt's own iterations, run in numpy on the QP's structure (_InteriorPoint; ~4e-13 from rps's
commands), or with bit_exact=True rps's very call of cvxopt.solvers.qp, so a command agrees with
the official simulator's and the lab's. The C++ twin,
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

# rps's cvxopt settings, passed to each call (rps sets them globally for every cvxopt user), and
# the ones _InteriorPoint follows. A certificate made with bit_exact=True hands rps's dense problem
# to cvxopt.solvers.qp, bit for bit (the check-submission stand-in's do, so its start-up drive is
# the official one); otherwise cvxopt's iterations run in numpy (answers within ~1e-11 of rps's).
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
    """min |v - vhat|^2 s.t. A v <= b as rps builds and solves it (cvxopt.solvers.qp on the dense
    problem, bit for bit); None when cvxopt does not end 'optimal' (rps then commands zeros)."""
    cvxopt = _cvxopt()
    n = vhat.shape[1]
    H = cvxopt.spmatrix(2.0, range(2 * n), range(2 * n))
    f = cvxopt.matrix(-2.0 * vhat.reshape(-1, order="F"))
    try:
        solution = cvxopt.solvers.qp(H, f, cvxopt.matrix(A), cvxopt.matrix(b), options=dict(QP_OPTIONS))
    except (ArithmeticError, ValueError, ZeroDivisionError):
        return None
    if solution["status"] != "optimal":
        return None
    return np.reshape(np.array(solution["x"]), (2, n), order="F")


class _RowLayout:
    """Where the rows of an n-robot certificate sit, in rps's order: one per pair i < j (i outer, j
    inner), then with a boundary four walls per robot (top, bottom, right, left), then the speed
    octagon's eight sides per robot. Each row touches at most two robots' 2-column blocks, and all
    but the pair rows are the same every step."""

    WALLS = np.array([[0.0, 1.0], [0.0, -1.0], [1.0, 0.0], [-1.0, 0.0]])
    _D = 1 / np.sqrt(2)
    OCTAGON = np.array([[1, 0], [_D, _D], [0, 1], [-_D, _D], [-1, 0], [-_D, -_D], [0, -1], [_D, -_D]])

    def __init__(self, n, walls, magnitude_limit, first_side_unscaled):
        self.n, self.size, self.walls = n, 2 * n, walls
        self.first, self.second = np.triu_indices(n, k=1)
        pairs = self.first.size
        robots = np.arange(n)
        self.robots = np.concatenate(([np.repeat(robots, 4)] if walls else []) + [np.repeat(robots, 8)])
        self.sides = np.concatenate(([np.tile(self.WALLS, (n, 1))] if walls else []) + [np.tile(self.OCTAGON, (n, 1))])
        bounds = np.full(8, magnitude_limit * np.cos(np.pi / 8))
        if first_side_unscaled:  # rps's certificate without boundary bounds its first side by the limit itself
            bounds[0] = magnitude_limit
        self.octagon_bounds = np.tile(bounds, n)
        self.row_count = pairs + self.robots.size
        pair_rows, single_rows = np.arange(pairs), pairs + np.arange(self.robots.size)
        # A's entries (row, column): a pair's -2 (x_i - x_j) at i's columns and +2 (x_i - x_j) at j's;
        # cvxopt's sparse matrices keep them column by column (ccs_order).
        f, s, r = 2 * self.first, 2 * self.second, 2 * self.robots
        self.rows = np.concatenate((pair_rows, pair_rows, pair_rows, pair_rows, single_rows, single_rows))
        self.columns = np.concatenate((f, f + 1, s, s + 1, r, r + 1))
        self.ccs_order = np.lexsort((self.rows, self.columns))
        self.single_entries = np.concatenate((self.sides[:, 0], self.sides[:, 1]))
        self._reduced_matrix_places(pair_rows, single_rows)

    def _reduced_matrix_places(self, pair_rows, single_rows):
        """2 I + A' W^-2 A, its lower triangle (all the Cholesky reads), as one weighted bincount: a row
        adds w u u' to its robots' diagonal blocks (u the row's 2 entries at a robot's columns: the
        entries (0,0), (1,0), (1,1) of the 2 x 2 block), and a pair i < j's row alone w v u' = -w u u'
        to the block (j, i) below it; the 2 I comes last (so each diagonal sum is rounded as the sum
        plus 2), weighted by the weight vector's extra last element, 1."""
        diagonal_block = (np.array([0, 1, 1])[None, :], np.array([0, 0, 1])[None, :])
        whole_block = (np.array([0, 0, 1, 1])[None, :], np.array([0, 1, 0, 1])[None, :])

        def places(i, j, block):  # flat places in the column-major 2n x 2n matrix cvxopt factors
            return ((2 * j[:, None] + block[1]) * self.size + (2 * i[:, None] + block[0])).reshape(-1)

        diagonal = np.arange(self.size) * (self.size + 1)
        # Every product's place, in _InteriorPoint._set_pairs' order, and the row whose weight it takes.
        self.product_places = np.concatenate((places(self.first, self.first, diagonal_block),
                                              places(self.second, self.second, diagonal_block),
                                              places(self.robots, self.robots, diagonal_block),
                                              places(self.second, self.first, whole_block), diagonal))
        self.product_rows = np.concatenate((np.repeat(pair_rows, 3), np.repeat(pair_rows, 3),
                                            np.repeat(single_rows, 3), np.repeat(pair_rows, 4),
                                            np.full(self.size, self.row_count)))
        s0, s1 = self.sides[:, 0], self.sides[:, 1]
        self.single_products = np.stack((s0 * s0, s1 * s0, s1 * s1), axis=1).reshape(-1)
        self.identity_products = np.full(self.size, 2.0)

    def pair_parts(self, x, safety_radius, barrier_gain):
        """The pairs' x_i - x_j (2 x pairs) and bounds."""
        diff = x[:, self.first] - x[:, self.second]
        h = diff[0] * diff[0] + diff[1] * diff[1] - safety_radius ** 2
        return diff, barrier_gain * (h ** 3)

    def bounds(self, x, safety_radius, barrier_gain, boundary, pair_bounds):
        """b of A v <= b: the pairs', the walls' (0.4 gain gap^3 each) and the octagon's."""
        parts = [pair_bounds]
        if self.walls:
            bp, half = boundary, safety_radius / 2
            gaps = np.stack((bp[3] - half - x[1], x[1] - bp[2] - half, bp[1] - half - x[0], x[0] - bp[0] - half), axis=1)
            parts.append((0.4 * barrier_gain * gaps ** 3).reshape(-1))  # elementwise: as each wall's own
        parts.append(self.octagon_bounds)
        return np.concatenate(parts)

    def dense(self, diff):
        """rps's dense A (rows x 2n), the same numbers in the same places."""
        A = np.zeros((self.row_count, self.size))
        pairs = np.arange(self.first.size)
        singles = self.first.size + np.arange(self.robots.size)
        for axis in (0, 1):
            A[pairs, 2 * self.first + axis] = -2 * diff[axis]
            A[pairs, 2 * self.second + axis] = 2 * diff[axis]
            A[singles, 2 * self.robots + axis] = self.sides[:, axis]
        return A


class _InteriorPoint:
    """cvxopt's coneqp (cvxopt/coneprog.py) for one layout's QPs, with `options` (rps's reltol,
    feastol, maxiters): its start, its predictor-corrector steps with Mehrotra's correction and its
    stopping test, step for step (the inequalities are its 'l' cone alone, which makes every scaling
    elementwise). solve(diff, q, h) gives the x of an 'optimal' end, or None where cvxopt would not
    end 'optimal' (a singular KKT matrix, non-finite data, the iteration limit). Not reentrant: every
    call reuses its buffers. Its time is numpy's and cvxopt's cost per call more than arithmetic
    (430 rows at 20 robots), so an iteration makes few calls: A's products are cvxopt's sparse gemv
    on a pattern built once, the vectors cvxopt reads and writes are cvxopt matrices seen from numpy
    without copies, and paired vectors (s and z, d and its inverse) sit in one array so that one call
    updates both (docs/performance.md#in-python)."""

    def __init__(self, layout, cvxopt, options):
        self.layout, self.options = layout, options
        m, size = layout.row_count, layout.size
        self.gemv, self.potrf, self.potrs, self.matrix = cvxopt.base.gemv, cvxopt.lapack.potrf, cvxopt.lapack.potrs, \
            cvxopt.matrix
        order = layout.ccs_order
        self.A = cvxopt.spmatrix(1.0, layout.rows[order], layout.columns[order], (m, size))
        if list(self.A.I) != layout.rows[order].tolist() or list(self.A.J) != layout.columns[order].tolist():
            raise AssertionError("cvxopt reordered the certificate's sparse rows")  # values are set in this order
        # cvxopt matrices and their numpy views: the reduced matrix, [z; s], A' W^-2 bz and then ux, W^-2 bz, A ux.
        self.factored = cvxopt.matrix(0.0, (size, size))
        self.zs_c, self.rx_c, self.rhs_c = cvxopt.matrix(0.0, (2 * m, 1)), cvxopt.matrix(0.0, (size, 1)), \
            cvxopt.matrix(0.0, (size, 1))
        self.wbz_c, self.gux_c = cvxopt.matrix(0.0, (m, 1)), cvxopt.matrix(0.0, (m, 1))
        self.reduced = np.asarray(self.factored).reshape(-1, order="F")  # a view, column-major
        self.zs, self.rx, self.rhs = np.frombuffer(self.zs_c).reshape(2, m), np.frombuffer(self.rx_c), \
            np.frombuffer(self.rhs_c)
        self.wbz, self.gux = np.frombuffer(self.wbz_c), np.frombuffer(self.gux_c)
        self.z, self.s = self.zs
        self.weights = np.ones(m + 1)  # W^-2's diagonal, and a 1 for the reduced matrix's 2 I
        self.row_weights = self.weights[:-1]
        self.scaling = np.empty((2, m))  # d^-1 and d: [z; s] = lmbda [d^-1; d]
        self.di, self.d = self.scaling
        self.lmbda, self.lmbda_squared, self.rz, self.gx = (np.empty(m) for _ in range(4))
        self.scaled = np.empty((2, m))  # the corrected ds and dz, scaled
        self.work = [np.empty(m) for _ in range(3)]
        self.x, self.x_step = np.empty(size), np.empty(size)
        self._pair_sources()
        self.products = None

    def solve(self, diff, q, h):
        if not (np.all(np.isfinite(q)) and np.all(np.isfinite(h))):
            return None
        self._set_pairs(diff)
        # Where cvxopt's elementwise operations raise (a zero divisor, a square root of a negative), these do too.
        with np.errstate(divide="raise", invalid="raise"):
            try:
                return self._iterate(q, h)
            except (ArithmeticError, FloatingPointError):
                return None

    def _pair_sources(self):
        """One vector the step's pair numbers are written into, [u; -u; uu; -uu] (u = -2 (x_i - x_j),
        2 x pairs; uu its products u0 u0, u1 u0, u1 u1, 3 x pairs), then the rows that never change;
        and where A's entries (in cvxopt's order) and the reduced matrix's products
        (_RowLayout.product_places) take theirs from it."""
        layout = self.layout
        pairs = layout.first.size
        fixed = np.concatenate((layout.single_entries, layout.single_products, layout.identity_products))
        self.sources = np.concatenate((np.empty(10 * pairs), fixed))
        self.u, self.negated_u = self.sources[:2 * pairs].reshape(2, pairs), self.sources[2 * pairs:4 * pairs]
        self.uu, self.negated_uu = self.sources[4 * pairs:7 * pairs].reshape(3, pairs), self.sources[7 * pairs:10 * pairs]
        single_entries, single_products = 10 * pairs, 10 * pairs + layout.single_entries.size
        identity = single_products + layout.single_products.size
        entries = np.concatenate((np.arange(4 * pairs), single_entries + np.arange(layout.single_entries.size)))
        self.entry_sources = entries[layout.ccs_order]
        k = np.arange(pairs)[:, None]
        # A pair's u u' = v v' = 4 (x_i - x_j)(x_i - x_j)' on both diagonal blocks, and v u' = -u u' below.
        diagonal = (4 * pairs + np.array([0, 1, 2]) * pairs + k).reshape(-1)
        below = (7 * pairs + np.array([0, 1, 1, 2]) * pairs + k).reshape(-1)
        self.product_sources = np.concatenate((diagonal, diagonal, single_products + np.arange(layout.single_products.size),
                                               below, identity + np.arange(layout.size)))

    def _set_pairs(self, diff):
        """A's pair entries, and the products they add to the reduced matrix, for the step's x_i - x_j."""
        u, uu = self.u, self.uu
        np.multiply(diff, -2, out=u)
        np.negative(u, out=self.negated_u.reshape(u.shape))
        np.multiply(u[[0, 1, 1]], u[[0, 0, 1]], out=uu)
        np.negative(uu, out=self.negated_uu.reshape(uu.shape))
        self.A.V = self.matrix(self.sources[self.entry_sources])
        self.products = self.sources[self.product_sources]

    def _iterate(self, q, h):
        reltol, feastol, abstol, maxiters = self.options["reltol"], self.options["feastol"], 1e-7, \
            self.options["maxiters"]
        x, rx, rz, z, s, gx = self.x, self.rx, self.rz, self.z, self.s, self.gx
        self._start(q, h)
        resx0, resz0 = max(1.0, math.sqrt(q.dot(q))), max(1.0, math.sqrt(h.dot(h)))
        gap = float(s.dot(z))
        for iteration in range(maxiters + 1):
            np.multiply(x, 2.0, out=rx)
            rx += q
            f0 = 0.5 * float(x.dot(rx) + x.dot(q))
            self.gemv(self.A, self.zs_c, self.rx_c, trans="T", beta=1.0)  # rx += A' z
            np.subtract(s, h, out=rz)
            rz += gx
            pcost, dcost = f0, f0 + float(z.dot(rz)) - gap
            relgap = gap / -pcost if pcost < 0.0 else (gap / dcost if dcost > 0.0 else None)
            pres, dres = math.sqrt(rz.dot(rz)) / resz0, math.sqrt(rx.dot(rx)) / resx0
            if iteration == maxiters:  # cvxopt's status 'unknown', converged or not
                return None
            if pres <= feastol and dres <= feastol and (gap <= abstol or (relgap is not None and relgap <= reltol)):
                return x.copy()
            if iteration == 0:
                np.sqrt(s / z, out=self.d)
                np.sqrt(s * z, out=self.lmbda)
                np.reciprocal(self.d, out=self.di)
                np.multiply(self.lmbda, self.lmbda, out=self.lmbda_squared)
            self._step(h, gap)
            gap = float(self.lmbda.dot(self.lmbda))
        return None

    def _start(self, q, h):
        """coneqp's starting point: the KKT system with W = I, s and z moved into the cone; x, A x."""
        self.scaling.fill(1.0)
        self._factor()
        self._kkt_solve(q, h, False, self.z)
        self.x[:] = self.rhs
        self.gx[:] = self.gux
        np.negative(self.z, out=self.s)
        for v in (self.s, self.z):
            t = -v.min()
            if t >= -1e-8 * max(math.sqrt(v.dot(v)), 1.0):
                v += 1.0 + t

    def _factor(self):
        """The reduced matrix 2 I + A' W^-2 A for the current scaling, factored (cvxopt's LAPACK potrf).
        ArithmeticError when it is not positive definite (only with non-finite data), as cvxopt's own
        factoring fails."""
        layout, weights = self.layout, self.weights
        np.multiply(self.di, self.di, out=self.row_weights)
        self.reduced[:] = np.bincount(layout.product_places, self.products * weights[layout.product_rows],
                                      minlength=self.reduced.size)
        self.potrf(self.factored)

    def _kkt_solve(self, rx, bz, negated, uz):
        """cvxopt's KKT system [2I A'; A -W'W] [ux; W^-1 uz] = [-rx; bz] with the factored scaling: ux in
        self.rhs, A ux in self.gux, uz into `uz`. `negated`: bz holds -bz (which spares a negation)."""
        np.multiply(self.row_weights, bz, out=self.wbz)
        self.rhs[:] = rx
        self.gemv(self.A, self.wbz_c, self.rhs_c, trans="T", alpha=-1.0 if negated else 1.0, beta=-1.0)
        self.potrs(self.factored, self.rhs_c)
        self.gemv(self.A, self.rhs_c, self.gux_c)
        (np.add if negated else np.subtract)(self.gux, bz, out=uz)
        uz *= self.di

    def _step(self, h, gap):
        """One coneqp iteration: the affine and the corrected direction, the step to 0.99 of the
        boundary, and the Nesterov-Todd scaling d and scaled point lmbda = W z = W^-T s updated, with
        x, A x, s and z. The affine direction's right-hand side is -lmbda o lmbda, which the step
        scales back by lmbda: -lmbda, and its z part -rz + d lmbda = s - rz."""
        lmbda, d, rz, scaled = self.lmbda, self.d, self.rz, self.scaled
        dz, negated_ds, correction = self.work
        self._factor()
        np.subtract(self.s, rz, out=correction)
        self._kkt_solve(self.rx, correction, False, dz)
        np.add(lmbda, dz, out=negated_ds)  # the affine ds = -lmbda - dz
        dsdz = -float(negated_ds.dot(dz))
        np.multiply(negated_ds, dz, out=correction)  # -(ds o dz)
        np.subtract(self.lmbda_squared, correction, out=correction)  # lmbda o lmbda + ds o dz
        scaled_dz = np.divide(dz, lmbda, out=dz)  # and ds / lmbda = -1 - scaled_dz
        t = max(0.0, 1.0 + float(np.maximum.reduce(scaled_dz)), -float(np.minimum.reduce(scaled_dz)))
        step = 1.0 if t == 0 else min(1.0, 1.0 / t)
        sigma = min(1.0, max(0.0, 1.0 - step + dsdz / gap * step ** 2)) ** 3
        # The corrected direction: right-hand side -lmbda o lmbda - (ds o dz) + sigma mu e, scaled by lmbda.
        ds = np.subtract(sigma * (gap / lmbda.size), correction, out=correction)
        ds /= lmbda
        negated_bz = np.multiply(ds, d, out=negated_ds)  # bz = -rz - ds o d
        negated_bz += rz
        self._kkt_solve(self.rx, negated_bz, True, scaled[1])
        np.subtract(ds, scaled[1], out=scaled[0])
        scaled /= lmbda
        t = max(0.0, -float(np.minimum.reduce(scaled, axis=None)))
        step = 1.0 if t == 0 else min(1.0, 0.99 / t)
        scaled *= step
        scaled += 1.0
        scaled *= lmbda
        ds, dz = np.sqrt(scaled, out=scaled)
        self.gux *= step  # A dx
        self.gx += self.gux
        np.multiply(self.rhs, step, out=self.x_step)  # dx
        self.x += self.x_step
        d *= ds
        d /= dz
        np.multiply(ds, dz, out=lmbda)
        np.reciprocal(d, out=self.di)
        np.multiply(lmbda, self.scaling, out=self.zs)
        np.multiply(lmbda, lmbda, out=self.lmbda_squared)


def _qp_solver(safety_radius, barrier_gain, magnitude_limit, boundary, bit_exact):
    """The certificate's QP for 2 x N points x and wanted velocities dxi (N >= 2, checked by the
    caller): the safe velocities, or None where rps's cvxopt call does not end 'optimal'."""
    cvxopt = _cvxopt()  # fail at creation, naming the package, rather than at the first step
    safety_radius = _positive("safety_radius", safety_radius)
    barrier_gain = _positive("barrier_gain", barrier_gain)
    magnitude_limit = _positive("magnitude_limit", magnitude_limit)
    solvers = {}  # by robot count: its _RowLayout and the _InteriorPoint with its buffers

    def solve(dxi, x):
        n = dxi.shape[1]
        if n not in solvers:
            if len(solvers) >= 8:  # a few sizes kept (a script's robots, with and without obstacle points)
                solvers.clear()
            layout = _RowLayout(n, boundary is not None, magnitude_limit, boundary is None)
            solvers[n] = (layout, None if bit_exact else _InteriorPoint(layout, cvxopt, QP_OPTIONS))
        layout, interior_point = solvers[n]
        diff, pair_bounds = layout.pair_parts(x, safety_radius, barrier_gain)
        b = layout.bounds(x, safety_radius, barrier_gain, boundary, pair_bounds)
        if bit_exact:
            return _solve_qp(np.copy(dxi), layout.dense(diff), b)
        solution = interior_point.solve(diff, -2.0 * dxi.reshape(-1, order="F"), b)
        return None if solution is None else np.reshape(solution, (2, n), order="F")

    return solve


def _single_integrator(safety_radius, barrier_gain, magnitude_limit, boundary, name, bit_exact):
    solve = _qp_solver(safety_radius, barrier_gain, magnitude_limit, boundary, bit_exact)

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
        v = solve(dxi, x)
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
    solve = _qp_solver(_positive("safety_radius", safety_radius) + 2 * d, barrier_gain, velocity_magnitude_limit,
                       boundary, bit_exact)

    def barrier_unicycle(dxu, x, obstacles=None):
        dxu = _columns("dxu", dxu, 2)
        x = _columns("x", x, 3)
        n = dxu.shape[1]
        if x.shape[1] != n:
            raise ValueError("dxu has %d columns, x %d" % (n, x.shape[1]))
        if n < 2:
            return dxu
        # The point d ahead of each robot, and its velocity: R(theta) diag(1, d) (v, w).
        cos, sin = np.cos(x[2, :]), np.sin(x[2, :])
        xi = x[0:2, :] + d * np.array([cos, sin])
        # Rounded as rps's R @ T @ dxu rounds (matmul sums from +0.0), so the certificate is rps's bit for bit.
        dxi = np.array([0.0 + cos * dxu[0, :] + (-sin * d) * dxu[1, :], 0.0 + sin * dxu[0, :] + (cos * d) * dxu[1, :]])
        if obstacles is not None and np.size(obstacles) > 0:
            obstacles = _columns("obstacles", obstacles, 2)
            xi = np.hstack((xi, obstacles))
            dxi = np.hstack((dxi, np.zeros((2, obstacles.shape[1]))))
        safe = solve(dxi, xi)
        if safe is None:
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
