#include "dream/barriers/interior_point_qp.h"

#include <algorithm>
#include <cmath>

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
  z->array() *= inverse_scale.array();
  work_m_ = z->cwiseProduct(inverse_scale);
  g.MultiplyTransposed(work_m_, &work_n_);
  *x += work_n_;
  cholesky_.SolveInPlace(x);
  g.Multiply(*x, &work_m_);
  *z = work_m_.cwiseProduct(inverse_scale) - *z;
}

QpSolution InteriorPointQp::Solve(const Eigen::VectorXd& p, const Eigen::VectorXd& q,
                                                  const LinearInequalities& constraints) {
  const LinearInequalities& g = constraints;
  const int m = g.num_rows();
  const Eigen::Map<const Eigen::VectorXd> h(g.bounds().data(), m);
  QpSolution solution;
  solution.x = Eigen::VectorXd::Zero(g.num_variables());
  if (!AllFinite(p) || !AllFinite(q) || !h.allFinite()) return solution;
  if (m == 0) {  // no constraint: the unconstrained minimum
    solution.x = -q.cwiseQuotient(p);
    solution.status = QpStatus::kOptimal;
    return solution;
  }
  const double resx0 = std::max(1.0, q.norm());
  const double resz0 = std::max(1.0, h.norm());

  // The starting point: the KKT system with W = I, then s and z moved inside the orthant.
  Eigen::VectorXd d = Eigen::VectorXd::Ones(m);
  Eigen::VectorXd di = Eigen::VectorXd::Ones(m);
  solution.status = QpStatus::kSingularSystem;
  if (!Factor(p, g, di)) return solution;
  Eigen::VectorXd x = -q;
  Eigen::VectorXd z = h;
  SolveKkt(g, di, &x, &z);
  Eigen::VectorXd s = -z;
  const double ts0 = MaxStep(s);
  if (ts0 >= -1e-8 * std::max(s.norm(), 1.0)) s.array() += 1.0 + ts0;
  const double tz0 = MaxStep(z);
  if (tz0 >= -1e-8 * std::max(z.norm(), 1.0)) z.array() += 1.0 + tz0;
  double gap = s.dot(z);

  Eigen::VectorXd lambda(m), lambda_sq(m), inverse_lambda(m), rx, rz, gz, dx, dz, ds, correction(m);
  for (int iteration = 0; iteration <= settings_.max_iterations; ++iteration) {
    solution.iterations = iteration;
    rx = p.cwiseProduct(x) + q;
    const double f0 = 0.5 * (x.dot(rx) + x.dot(q));
    g.MultiplyTransposed(z, &work_n_);
    rx += work_n_;
    const double resx = rx.norm();
    g.Multiply(x, &gz);
    rz = s - h + gz;
    const double resz = rz.norm();
    const double pcost = f0;
    const double dcost = f0 + z.dot(rz) - gap;
    const bool has_relgap = pcost < 0.0 || dcost > 0.0;
    const double relgap = pcost < 0.0 ? gap / -pcost : (dcost > 0.0 ? gap / dcost : 0.0);
    const double pres = resz / resz0;
    const double dres = resx / resx0;
    if (!std::isfinite(pres) || !std::isfinite(dres) || !std::isfinite(gap) || !AllFinite(x)) {
      solution.status = QpStatus::kNotFinite;
      return solution;
    }
    solution.x = x;
    const bool converged = pres <= settings_.feasibility_tolerance && dres <= settings_.feasibility_tolerance &&
                           (gap <= settings_.absolute_gap_tolerance ||
                            (has_relgap && relgap <= settings_.relative_gap_tolerance));
    if (converged) {
      solution.status = QpStatus::kOptimal;
      return solution;
    }
    if (iteration == settings_.max_iterations) {
      solution.status = QpStatus::kIterationLimit;
      return solution;
    }
    if (iteration == 0) {  // the Nesterov-Todd scaling of the starting point
      d = (s.array() / z.array()).sqrt();
      di = (z.array() / s.array()).sqrt();
      lambda = (s.array() * z.array()).sqrt();
    }
    lambda_sq = lambda.cwiseProduct(lambda);
    inverse_lambda = lambda.cwiseInverse();  // multiplied by below: six divisions of m fewer per iteration
    if (!Factor(p, g, di)) {
      solution.status = QpStatus::kSingularSystem;
      return solution;
    }
    if (gap == 0.0) {  // CVXOPT divides by it below and raises
      solution.status = QpStatus::kNotFinite;
      return solution;
    }
    const double mu = gap / m;
    double sigma = 0.0;
    double step = 1.0;
    for (int pass = 0; pass < 2; ++pass) {
      // Predictor (pass 0), then corrector with Mehrotra's second-order term (pass 1).
      ds = -lambda_sq;
      if (pass == 1) ds -= correction;
      ds.array() += sigma * mu;
      dx = -rx;
      dz = -rz;
      ds.array() *= inverse_lambda.array();
      dz -= d.cwiseProduct(ds);
      SolveKkt(g, di, &dx, &dz);
      ds -= dz;
      const double dsdz = ds.dot(dz);
      if (pass == 0) correction = ds.cwiseProduct(dz);
      ds.array() *= inverse_lambda.array();
      dz.array() *= inverse_lambda.array();
      const double t = std::max({0.0, MaxStep(ds), MaxStep(dz)});
      if (t == 0.0) {
        step = 1.0;
      } else {
        step = std::min(1.0, (pass == 0 ? 1.0 : kCorrectorStepFraction) / t);
      }
      if (pass == 0) {
        sigma = std::pow(std::min(1.0, std::max(0.0, 1.0 - step + dsdz / gap * step * step)), kCenteringExponent);
      }
    }
    x += step * dx;
    ds = ((1.0 + step * ds.array()) * lambda.array()).sqrt();
    dz = ((1.0 + step * dz.array()) * lambda.array()).sqrt();
    d = (d.array() * ds.array()) / dz.array();
    di = d.cwiseInverse();
    lambda = ds.cwiseProduct(dz);
    s = d.cwiseProduct(lambda);
    z = di.cwiseProduct(lambda);
    gap = lambda.dot(lambda);
  }
  solution.status = QpStatus::kIterationLimit;
  return solution;
}

}  // namespace dream::barriers
