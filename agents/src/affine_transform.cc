#include "dream/agents/geometry/affine_transform.h"

#include <Eigen/Dense>

namespace dream::agents {

std::optional<AffineTransform> AffineTransform::Fit(const std::vector<Eigen::Vector2d>& from,
                                                    const std::vector<Eigen::Vector2d>& to) {
  if (from.size() != to.size() || from.size() < 3) return std::nullopt;
  const auto k = static_cast<Eigen::Index>(from.size());
  // Rows [r_x, r_y, 1]; solve X [A^T; b^T] = P in the least-squares sense.
  Eigen::MatrixXd x(k, 3);
  Eigen::MatrixXd p(k, 2);
  for (Eigen::Index i = 0; i < k; ++i) {
    const auto s = static_cast<size_t>(i);
    if (!from[s].allFinite() || !to[s].allFinite()) return std::nullopt;
    x.row(i) << from[s].x(), from[s].y(), 1.0;
    p.row(i) = to[s].transpose();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(x, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  // Collinear points leave X rank-deficient: A would be arbitrary across the line.
  if (!(sigma(2) > 1e-9 * sigma(0))) return std::nullopt;
  const Eigen::MatrixXd solution = svd.solve(p);  // 3x2
  AffineTransform transform;
  transform.linear = solution.topRows(2).transpose();
  transform.translation_m = solution.row(2).transpose();
  return transform;
}

}  // namespace dream::agents
