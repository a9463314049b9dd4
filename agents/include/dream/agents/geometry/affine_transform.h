#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace dream::agents {

/// A planar affine map p = A r + b (Zhao 2018's target formation: an affine
/// image of the nominal configuration).
struct AffineTransform {
  Eigen::Matrix2d linear = Eigen::Matrix2d::Identity();     ///< A
  Eigen::Vector2d translation_m = Eigen::Vector2d::Zero();  ///< b, metres

  Eigen::Vector2d Apply(const Eigen::Vector2d& r) const { return linear * r + translation_m; }

  /// The least-squares (A, b) with A from[k] + b ~= to[k]. Exact for three
  /// points in general position. Nothing when the sizes differ or `from` does
  /// not span the plane affinely (fewer than 3 points, or all on one line),
  /// because then A is not determined.
  static std::optional<AffineTransform> Fit(const std::vector<Eigen::Vector2d>& from,
                                            const std::vector<Eigen::Vector2d>& to);
};

}  // namespace dream::agents
