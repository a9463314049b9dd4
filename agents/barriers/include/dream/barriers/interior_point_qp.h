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
  /// How far the current iterate is from optimal, as coneqp measures it.
  struct Residuals {
    double primal = 0.0;  ///< |s + G x - h| / max(1, |h|)
    double dual = 0.0;    ///< |P x + q + G' z| / max(1, |q|)
    double relative_gap = 0.0;
    bool has_relative_gap = false;  ///< CVXOPT's relgap is None when neither cost has the right sign
  };

  /// The starting point (x, s, z, gap); false when S cannot be factored.
  bool Start(const Eigen::VectorXd& p, const Eigen::VectorXd& q, const LinearInequalities& g);
  /// rx, rz and the stopping figures of the current iterate.
  Residuals ComputeResiduals(const Eigen::VectorXd& p, const Eigen::VectorXd& q, const LinearInequalities& g);
  bool Converged(const Residuals& residuals) const;
  /// One predictor-corrector step; kOptimal when it was taken, else why not.
  QpStatus Step(const Eigen::VectorXd& p, const LinearInequalities& g, bool first);
  /// S = diag(p) + G' diag(scale)^2 G, factored; false when not positive definite.
  bool Factor(const Eigen::VectorXd& p, const LinearInequalities& g, const Eigen::VectorXd& inverse_scale);
  /// The reduced KKT solve of coneqp's kkt_chol2: on entry bx, bz; on exit ux and W uz.
  void SolveKkt(const LinearInequalities& g, const Eigen::VectorXd& inverse_scale, Eigen::VectorXd* x,
                Eigen::VectorXd* z);

  QpSettings settings_;
  DenseCholesky cholesky_;
  // The iterate and the scaling W = diag(d) (di = 1/d), lambda = W z = W^-T s.
  Eigen::VectorXd x_, s_, z_, d_, di_, lambda_;
  double gap_ = 0.0;
  // Work vectors, kept so that a solver per run allocates once.
  Eigen::VectorXd rx_, rz_, dx_, dz_, ds_, inverse_lambda_, correction_;
  Eigen::VectorXd work_n_;
  Eigen::VectorXd work_m_;
};

}  // namespace dream::barriers
