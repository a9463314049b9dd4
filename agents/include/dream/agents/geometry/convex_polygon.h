#pragma once

#include <Eigen/Core>
#include <vector>

#include "dream/agents/geometry/half_plane.h"

namespace dream::agents {

/// A convex polygon, vertices counter-clockwise. Voronoi cells are built by
/// clipping one with half-planes (Sutherland-Hodgman against one edge at a
/// time), so they stay exact polygons: area, centroid and second moment come
/// from closed formulas, not from sampling.
class ConvexPolygon {
 public:
  ConvexPolygon() = default;
  /// @param vertices counter-clockwise, convex (not checked).
  explicit ConvexPolygon(std::vector<Eigen::Vector2d> vertices) : vertices_(std::move(vertices)) {}

  /// The axis-aligned rectangle [min, max]; empty when min > max on an axis.
  static ConvexPolygon Rectangle(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m);
  /// The regular polygon with `sides` vertices on the circle (centre,
  /// radius): inscribed, so it never reaches beyond the circle. sides >= 3.
  static ConvexPolygon RegularPolygon(const Eigen::Vector2d& center_m, double radius_m, int sides);

  /// Keeps the part inside `plane`. Points on the line count as inside.
  ConvexPolygon Clipped(const HalfPlane& plane) const;
  void Clip(const HalfPlane& plane) { *this = Clipped(plane); }
  /// The part inside the axis-aligned box [min, max].
  ConvexPolygon ClippedToBox(const Eigen::Vector2d& min_m, const Eigen::Vector2d& max_m) const;

  const std::vector<Eigen::Vector2d>& vertices() const { return vertices_; }
  /// Fewer than 3 vertices or no area.
  bool empty() const { return vertices_.size() < 3 || !(Area() > 0.0); }
  /// Square metres (>= 0 for counter-clockwise vertices).
  double Area() const;
  /// The centroid of the area; the vertex mean when the area vanishes.
  Eigen::Vector2d Centroid() const;
  /// The first moment: integral over the polygon of q dq (m^3), = Area() x Centroid().
  Eigen::Vector2d FirstMoment() const;
  /// The polar second moment about `point`: integral over the polygon of
  /// ||q - point||^2 dq (m^4), the coverage cost of one Voronoi cell.
  double SecondMoment(const Eigen::Vector2d& point) const;
  bool Contains(const Eigen::Vector2d& point, double tolerance_m = 1e-12) const;
  /// The point of the polygon closest to `point` (itself when inside).
  /// `point` when the polygon has no vertices.
  Eigen::Vector2d ClosestPoint(const Eigen::Vector2d& point) const;

 private:
  std::vector<Eigen::Vector2d> vertices_;
};

}  // namespace dream::agents
