#pragma once

#include <Eigen/Core>
#include <optional>

namespace dream::agents {

/// The closed half-plane {x : normal . x <= offset}, normal of unit length.
/// The building block of Voronoi cells: every neighbour, obstacle and wall
/// cuts a cell with one of these.
struct HalfPlane {
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();
  double offset = 0.0;

  /// Positive inside, negative outside: how far `x` may move along `normal`
  /// before it leaves (metres, as the normal has unit length).
  double Slack(const Eigen::Vector2d& x) const { return offset - normal.dot(x); }
  bool Contains(const Eigen::Vector2d& x) const { return Slack(x) >= 0.0; }

  /// The points closer to `self` than to `other` (the Voronoi bisector),
  /// moved `buffer_m` towards `self` (a buffered Voronoi cell: two robots
  /// that each stay on their side keep 2 buffer_m apart). Nothing when the
  /// two points coincide (no bisector).
  static std::optional<HalfPlane> Bisector(const Eigen::Vector2d& self, const Eigen::Vector2d& other, double buffer_m) {
    const Eigen::Vector2d d = other - self;
    const double length = d.norm();
    if (!(length > 1e-12)) return std::nullopt;
    const Eigen::Vector2d n = d / length;
    return HalfPlane{n, n.dot(0.5 * (self + other)) - buffer_m};
  }

  /// The bisector between `self` and the virtual agent mirrored across the
  /// obstacle's closest point (self + 2 (closest - self), thesis Fig. 3.9):
  /// the line through `closest` facing `self`, which for a convex obstacle
  /// leaves the whole obstacle outside; moved `buffer_m` towards `self`.
  static std::optional<HalfPlane> AwayFromObstacle(const Eigen::Vector2d& self, const Eigen::Vector2d& closest,
                                                   double buffer_m) {
    return Bisector(self, self + 2.0 * (closest - self), buffer_m);
  }
};

}  // namespace dream::agents
