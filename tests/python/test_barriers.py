#!/usr/bin/python3
"""dream.barriers (python/dream/barriers.py) against the official Robotarium V2 barrier
certificates: tests/data/robotarium_v2_barriers.json holds rps's outputs on random states
(tests/robotarium_reference/generate_barrier_reference.py), the C++ barriers_test reads the same
file. Same solver, same settings: the commands must agree to 1e-9 (1e-5 is the issue's bar).

Exit code 77 (skipped) when numpy or cvxopt is missing (Debian: python3-cvxopt).
"""

import json
import os
import unittest
import warnings

from unit_setup import SOURCE_DIR, put_runtime_on_path, require_modules

require_modules("numpy", "cvxopt")  # cvxopt: what dream.barriers solves with
import numpy as np  # noqa: E402
put_runtime_on_path()

from dream import barriers  # noqa: E402

FIXTURE = os.path.join(SOURCE_DIR, "tests", "data", "robotarium_v2_barriers.json")
TOLERANCE = 1e-9


class ReferenceTest(unittest.TestCase):
    def test_same_commands_as_rps(self):
        with open(FIXTURE, encoding="utf-8") as f:
            cases = json.load(f)["cases"]
        self.assertGreaterEqual(len(cases), 20)
        failures = 0
        for index, case in enumerate(cases):
            with self.subTest(case=index, function=case["function"]):
                certificate = getattr(barriers, case["function"])(**case["params"])
                args = [np.array(case["dx"]), np.array(case["x"])]
                if "obstacles" in case:
                    args.append(np.array(case["obstacles"]))
                with warnings.catch_warnings(record=True) as caught:
                    warnings.simplefilter("always")
                    out = certificate(*args)
                failed = any("QP failed" in str(w.message) for w in caught)
                self.assertEqual(failed, case["qp_failed"])
                failures += failed
                np.testing.assert_allclose(out, np.array(case["expected"]), rtol=0, atol=TOLERANCE)
        self.assertGreaterEqual(failures, 1, "the fixture should hold a QP that fails")



class InteriorPointTest(unittest.TestCase):
    """dream.barriers runs cvxopt's iterations in numpy (_InteriorPoint), its KKT systems solved
    through the QP's structure (_RowLayout, A sparse); on the same QPs, cvxopt.solvers.qp on rps's dense
    problem (bit_exact=True) must give the same commands and fail where they fail: random states,
    crowded ones (where the QP fails), obstacle points included."""

    def test_same_commands_as_cvxopt(self):
        rng = np.random.default_rng(7)
        compared, failed_both = 0, 0
        for n in (2, 5, 12, 20):
            for crowded in (False, True):
                for _ in range(8):
                    spread = 0.4 if crowded else 1.3
                    x = np.vstack([rng.uniform(-spread, spread, n), rng.uniform(-spread * 0.6, spread * 0.6, n),
                                   rng.uniform(-np.pi, np.pi, n)])
                    dxu = np.vstack([rng.uniform(-0.2, 0.2, n), rng.uniform(-2, 2, n)])
                    obstacles = rng.uniform(-1, 1, (2, 2))
                    for make, args in ((barriers.create_uni_barrier_certificate_with_boundary, (dxu, x, obstacles)),
                                       (barriers.create_uni_barrier_certificate, (dxu, x)),
                                       (barriers.create_si_barrier_certificate_with_boundary, (dxu, x[:2]))):
                        outcomes = []
                        for bit_exact in (False, True):
                            with warnings.catch_warnings(record=True) as caught:
                                warnings.simplefilter("always")
                                out = make(bit_exact=bit_exact)(*args)
                            outcomes.append((out, any("QP failed" in str(w.message) for w in caught)))
                        (ours, we_failed), (theirs, they_failed) = outcomes
                        self.assertEqual(we_failed, they_failed, (n, crowded, make.__name__))
                        failed_both += we_failed
                        np.testing.assert_allclose(ours, theirs, rtol=0, atol=1e-9)
                        compared += 1
        self.assertEqual(compared, 192)
        self.assertGreaterEqual(failed_both, 1, "crowded states should include a QP that fails")

    def test_bit_exact_hands_cvxopt_rps_dense_problem(self):
        """bit_exact=True (the check-submission stand-in's certificates): cvxopt gets a dense G and
        its own KKT solver, as in rps; without it cvxopt.solvers.qp is not called at all."""
        import cvxopt
        import cvxopt.solvers
        real = cvxopt.solvers.qp
        calls = []

        def spy(P, q, G, h, kktsolver=None, **kwargs):
            calls.append((type(G).__name__, kktsolver))
            return real(P, q, G, h, kktsolver=kktsolver, **kwargs)

        rng = np.random.default_rng(11)
        n = 20
        x = np.vstack([rng.uniform(-1.3, 1.3, n), rng.uniform(-0.8, 0.8, n), rng.uniform(-np.pi, np.pi, n)])
        dxu = np.vstack([rng.uniform(-0.2, 0.2, n), rng.uniform(-2, 2, n)])
        try:
            cvxopt.solvers.qp = spy
            exact = barriers.create_uni_barrier_certificate_with_boundary(bit_exact=True)(dxu, x)
            fast = barriers.create_uni_barrier_certificate_with_boundary()(dxu, x)
        finally:
            cvxopt.solvers.qp = real
        self.assertEqual(calls, [("matrix", None)])  # rps's dense G, cvxopt's own KKT step; then none
        np.testing.assert_allclose(exact, fast, rtol=0, atol=1e-9)

    def test_non_finite_states_fail_as_cvxopt_fails(self):
        x = np.array([[0.0, 0.5, np.nan], [0.0, 0.0, 0.2], [0.0, 1.0, 2.0]])
        dxu = np.array([[0.1, 0.1, 0.1], [0.0, 0.0, 0.0]])
        for bit_exact in (False, True):
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                out = barriers.create_uni_barrier_certificate_with_boundary(bit_exact=bit_exact)(dxu, x)
            self.assertTrue(any("QP failed" in str(w.message) for w in caught), bit_exact)
            np.testing.assert_array_equal(out, np.zeros((2, 3)))


class InputTest(unittest.TestCase):
    def test_one_robot_passes_unchanged(self):
        dxu = np.array([[5.0], [9.0]])
        out = barriers.create_uni_barrier_certificate_with_boundary()(dxu, np.array([[1.59], [0.0], [0.0]]))
        np.testing.assert_array_equal(out, dxu)

    def test_bad_parameters_are_named(self):
        with self.assertRaisesRegex(ValueError, "projection_distance must be a positive number, got 0"):
            barriers.create_uni_barrier_certificate_with_boundary(projection_distance=0)
        with self.assertRaisesRegex(ValueError, "boundary_points must be"):
            barriers.create_si_barrier_certificate_with_boundary(boundary_points=[1, -1, 0, 1])
        with self.assertRaisesRegex(ValueError, "safety_radius"):
            barriers.create_si_barrier_certificate(safety_radius=float("nan"))

    def test_bad_shapes_are_named(self):
        certificate = barriers.create_uni_barrier_certificate_with_boundary()
        with self.assertRaisesRegex(ValueError, "x must be 3 x N"):
            certificate(np.zeros((2, 3)), np.zeros((2, 3)))
        with self.assertRaisesRegex(ValueError, "dxu has 3 columns, x 2"):
            certificate(np.zeros((2, 3)), np.zeros((3, 2)))

    def test_head_on_robots_are_slowed(self):
        poses = np.array([[-0.12, 0.12], [0.0, 0.0], [0.0, np.pi]])
        out = barriers.create_uni_barrier_certificate_with_boundary()(np.array([[0.2, 0.2], [0.0, 0.0]]), poses)
        self.assertLess(out[0, 0], 0.05)
        self.assertLess(out[0, 1], 0.05)


if __name__ == "__main__":
    unittest.main()
