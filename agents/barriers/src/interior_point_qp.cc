#include "dream/barriers/interior_point_qp.h"

#include <algorithm>
#include <cmath>

#include "orthant_kernels.h"

namespace dream::barriers {
namespace {

/// coneqp's step-length rule: the largest step keeping s and z inside the
/// orthant, times 0.99 for the corrector; sigma = (1 - step + ...)^3.
constexpr double kCorrectorStepFraction = 0.99;
constexpr int kCenteringExponent = 3;

/// min { t | v + t e >= 0 } for the orthant: the largest of -v.
double MaxStep(const Eigen::VectorXd& v) { return v.size() == 0 ? 0.0 : (-v).maxCoeff(); }

bool AllFinite(const Eigen::VectorXd& v) { return v.allFinite(); }

}  // namespace

bool InteriorPointQp::Factor(const Eigen::VectorXd& p, const LinearInequalities& g,
                             const Eigen::VectorXd& inverse_scale) {
  cholesky_.Reset(g.num_variables());
  // A run of rows of one robot (its walls, its speed octagon) adds to that
  // robot's 2 x 2 diagonal block only: summed here, added once.
  int run_block = LinearInequalities::kNoBlock;
  double s00 = 0.0, s10 = 0.0, s11 = 0.0;
  auto flush = [&] {
    if (run_block == LinearInequalities::kNoBlock) return;
    cholesky_.AddLower(2 * run_block, 2 * run_block, s00);
    cholesky_.AddLower(2 * run_block + 1, 2 * run_block, s10);
    cholesky_.AddLower(2 * run_block + 1, 2 * run_block + 1, s11);
    run_block = LinearInequalities::kNoBlock;
    s00 = s10 = s11 = 0.0;
  };
  for (int row = 0; row < g.num_rows(); ++row) {
    const double weight = inverse_scale[row] * inverse_scale[row];
    const double* c = g.coefficients(row);
    const int a = g.block_a(row);
    const int b = g.block_b(row);
    const double wa0 = weight * c[0];
    const double wa1 = weight * c[1];
    if (b == LinearInequalities::kNoBlock) {
      if (a != run_block) {
        flush();
        run_block = a;
      }
      s00 += wa0 * c[0];
      s10 += wa1 * c[0];
      s11 += wa1 * c[1];
      continue;
    }
    flush();
    const int a0 = 2 * a, a1 = 2 * a + 1, b0 = 2 * b, b1 = 2 * b + 1;
    const double wb0 = weight * c[2];
    const double wb1 = weight * c[3];
    cholesky_.AddLower(a0, a0, wa0 * c[0]);
    cholesky_.AddLower(a1, a0, wa1 * c[0]);
    cholesky_.AddLower(a1, a1, wa1 * c[1]);
    cholesky_.AddLower(b0, b0, wb0 * c[2]);
    cholesky_.AddLower(b1, b0, wb1 * c[2]);
    cholesky_.AddLower(b1, b1, wb1 * c[3]);
    cholesky_.AddLower(b0, a0, wb0 * c[0]);
    cholesky_.AddLower(b0, a1, wb0 * c[1]);
    cholesky_.AddLower(b1, a0, wb1 * c[0]);
    cholesky_.AddLower(b1, a1, wb1 * c[1]);
  }
  flush();
  cholesky_.AddDiagonal(p);
  return cholesky_.Factor();
}

void InteriorPointQp::SolveKkt(const LinearInequalities& g, const Eigen::VectorXd& inverse_scale, Eigen::VectorXd* x,
                               Eigen::VectorXd* z) {
  // z := W^-T bz; x := S^-1 (bx + G' W^-1 W^-T bz); W uz := W^-T (G ux - bz).
  const auto m = static_cast<size_t>(g.num_rows());
  work_m_.resize(g.num_rows());
  orthant::ScaleTwice(m, inverse_scale.data(), z->data(), work_m_.data());
  g.MultiplyTransposed(work_m_, &work_n_);
  *x += work_n_;
  cholesky_.SolveInPlace(x);
  g.Multiply(*x, &work_m_);
  orthant::ScaledDifference(m, work_m_.data(), inverse_scale.data(), z->data());
}

bool InteriorPointQp::Start(const Eigen::VectorXd& p, const Eigen::VectorXd& q, const LinearInequalities& g) {
  // The KKT system with W = I, then s and z moved inside the orthant.
  const int m = g.num_rows();
  d_ = Eigen::VectorXd::Ones(m);
  di_ = Eigen::VectorXd::Ones(m);
  if (!Factor(p, g, di_)) return false;
  x_ = -q;
  z_ = Eigen::Map<const Eigen::VectorXd>(g.bounds().data(), m);
  SolveKkt(g, di_, &x_, &z_);
  s_ = -z_;
  const double ts = MaxStep(s_);
  if (ts >= -1e-8 * std::max(s_.norm(), 1.0)) s_.array() += 1.0 + ts;
  const double tz = MaxStep(z_);
  if (tz >= -1e-8 * std::max(z_.norm(), 1.0)) z_.array() += 1.0 + tz;
  gap_ = s_.dot(z_);
  return true;
}

InteriorPointQp::Residuals InteriorPointQp::ComputeResiduals(const Eigen::VectorXd& p, const Eigen::VectorXd& q,
                                                             const LinearInequalities& g) {
  const Eigen::Map<const Eigen::VectorXd> h(g.bounds().data(), g.num_rows());
  rx_ = p.cwiseProduct(x_) + q;
  const double f0 = 0.5 * (x_.dot(rx_) + x_.dot(q));
  g.MultiplyTransposed(z_, &work_n_);
  rx_ += work_n_;
  g.Multiply(x_, &work_m_);
  rz_.resize(g.num_rows());
  orthant::PrimalResidual(static_cast<size_t>(g.num_rows()), s_.data(), h.data(), work_m_.data(), rz_.data());
  const double pcost = f0;
  const double dcost = f0 + z_.dot(rz_) - gap_;
  Residuals r;
  r.has_relative_gap = pcost < 0.0 || dcost > 0.0;
  r.relative_gap = pcost < 0.0 ? gap_ / -pcost : (dcost > 0.0 ? gap_ / dcost : 0.0);
  r.primal = rz_.norm() / std::max(1.0, h.norm());
  r.dual = rx_.norm() / std::max(1.0, q.norm());
  return r;
}

bool InteriorPointQp::Converged(const Residuals& r) const {
  return r.primal <= settings_.feasibility_tolerance && r.dual <= settings_.feasibility_tolerance &&
         (gap_ <= settings_.absolute_gap_tolerance ||
          (r.has_relative_gap && r.relative_gap <= settings_.relative_gap_tolerance));
}

QpStatus InteriorPointQp::Step(const Eigen::VectorXd& p, const LinearInequalities& g, bool first) {
  const auto m = static_cast<size_t>(g.num_rows());
  if (first) {  // the Nesterov-Todd scaling of the starting point
    d_ = (s_.array() / z_.array()).sqrt();
    di_ = (z_.array() / s_.array()).sqrt();
    lambda_ = (s_.array() * z_.array()).sqrt();
    inverse_lambda_ = lambda_.cwiseInverse();  // later steps get it from the scaling's update
  }
  if (!Factor(p, g, di_)) return QpStatus::kSingularSystem;
  if (gap_ == 0.0) return QpStatus::kNotFinite;  // CVXOPT divides by it below and raises
  const double mu = gap_ / static_cast<double>(m);
  ds_.resize(g.num_rows());
  dz_.resize(g.num_rows());
  correction_.resize(g.num_rows());
  double sigma = 0.0;
  double step = 1.0;
  for (int pass = 0; pass < 2; ++pass) {
    // Predictor (pass 0), then corrector with Mehrotra's second-order term (pass 1).
    orthant::Direction(m, sigma * mu, lambda_.data(), inverse_lambda_.data(), pass == 0 ? nullptr : correction_.data(),
                       d_.data(), rz_.data(), ds_.data(), dz_.data());
    dx_ = -rx_;
    SolveKkt(g, di_, &dx_, &dz_);
    orthant::Subtract(m, dz_.data(), ds_.data());
    const double dsdz = ds_.dot(dz_);
    orthant::Rescale(m, inverse_lambda_.data(), ds_.data(), dz_.data(), pass == 0 ? correction_.data() : nullptr);
    const double t = std::max({0.0, MaxStep(ds_), MaxStep(dz_)});
    step = t == 0.0 ? 1.0 : std::min(1.0, (pass == 0 ? 1.0 : kCorrectorStepFraction) / t);
    if (pass == 0) {
      sigma = std::pow(std::min(1.0, std::max(0.0, 1.0 - step + dsdz / gap_ * step * step)), kCenteringExponent);
    }
  }
  x_ += step * dx_;
  // The new s and z in the current scaling, then the scaling and lambda updated (orthant_kernels.h:
  // one square root a row where cvxopt takes two, the costliest instruction of a step).
  orthant::UpdateScaling(m, step, ds_.data(), dz_.data(), lambda_.data(), inverse_lambda_.data(), d_.data(), di_.data(),
                         s_.data(), z_.data());
  gap_ = lambda_.dot(lambda_);
  return QpStatus::kOptimal;
}

QpSolution InteriorPointQp::Solve(const Eigen::VectorXd& p, const Eigen::VectorXd& q,
                                  const LinearInequalities& constraints) {
  const LinearInequalities& g = constraints;
  const Eigen::Map<const Eigen::VectorXd> h(g.bounds().data(), g.num_rows());
  QpSolution solution;
  solution.x = Eigen::VectorXd::Zero(g.num_variables());
  if (!AllFinite(p) || !AllFinite(q) || !h.allFinite()) return solution;
  if (g.num_rows() == 0) {  // no constraint: the unconstrained minimum
    solution.x = -q.cwiseQuotient(p);
    solution.status = QpStatus::kOptimal;
    return solution;
  }
  solution.status = QpStatus::kSingularSystem;
  if (!Start(p, q, g)) return solution;
  for (int iteration = 0; iteration <= settings_.max_iterations; ++iteration) {
    solution.iterations = iteration;
    const Residuals residuals = ComputeResiduals(p, q, g);
    if (!std::isfinite(residuals.primal) || !std::isfinite(residuals.dual) || !std::isfinite(gap_) || !AllFinite(x_)) {
      solution.status = QpStatus::kNotFinite;
      return solution;
    }
    solution.x = x_;
    if (Converged(residuals)) {
      solution.status = QpStatus::kOptimal;
      return solution;
    }
    if (iteration == settings_.max_iterations) break;
    const QpStatus stepped = Step(p, g, iteration == 0);
    if (stepped != QpStatus::kOptimal) {
      solution.status = stepped;
      return solution;
    }
  }
  solution.status = QpStatus::kIterationLimit;
  return solution;
}

}  // namespace dream::barriers
