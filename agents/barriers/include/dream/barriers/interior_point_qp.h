#pragma once

#include <Eigen/Core>

#include "dream/barriers/dense_cholesky.h"
#include "dream/barriers/linear_inequalities.h"
#include "dream/barriers/qp_settings.h"
#include "dream/barriers/qp_solution.h"

namespace dream::barriers {

/// Solves   minimize (1/2) x' diag(p) x + q' x   subject to   G x <= h
/// by the primal-dual interior-point method of CVXOPT's `coneqp` for the
/// nonnegative orthant (L. Vandenberghe, "The CVXOPT linear and quadratic
/// cone program solvers", 2010): Nesterov-Todd scaling, Mehrotra's
/// predictor-corrector, the KKT system reduced to a Cholesky factorization of
/// diag(p) + G' W^-2 G, the same starting point and the same stopping tests.
///
/// Why not a packaged solver (docs/dependencies.md): the Robotarium's barrier
/// certificates stop CVXOPT early (relative gap and feasibility 1e-2), so the
/// commands the lab runs are that iterate, up to 1e-1 from the QP's exact
/// optimum. Only the same iteration gives the same commands (1e-5); an exact
/// solver (Clp, Ipopt) cannot.
class InteriorPointQp {
 public:
  explicit InteriorPointQp(QpSettings settings = QpSettings()) : settings_(settings) {}

  /// `p` is P's diagonal (positive), `q` the linear term, `constraints` G and h.
  /// Keeps its work vectors between calls, so a solver per run allocates once.
  QpSolution Solve(const Eigen::VectorXd& p, const Eigen::VectorXd& q, const LinearInequalities& constraints);

 private:
  /// S = diag(p) + G' diag(scale)^2 G, factored; false when not positive definite.
  bool Factor(const Eigen::VectorXd& p, const LinearInequalities& g, const Eigen::VectorXd& inverse_scale);
  /// The reduced KKT solve of coneqp's kkt_chol2: on entry bx, bz; on exit ux and W uz.
  void SolveKkt(const LinearInequalities& g, const Eigen::VectorXd& inverse_scale, Eigen::VectorXd* x,
                Eigen::VectorXd* z);

  QpSettings settings_;
  DenseCholesky cholesky_;
  Eigen::VectorXd work_n_;
  Eigen::VectorXd work_m_;
};

}  // namespace dream::barriers
