#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "dream/agents/geometry/convex_polygon.h"

namespace dream::agents {

/// The union of axis-aligned rectangles (obstacles), for integrals over the
/// part of a convex polygon they cover: by inclusion-exclusion, as a list of
/// boxes (the non-empty intersections of every subset) with signs +-1, so
/// overlapping obstacles are not counted twice.
class RectangleUnion {
 public:
  struct Box {
    Eigen::Vector2d min_m;
    Eigen::Vector2d max_m;
  };

  /// @param boxes rectangles; empty ones are ignored.
  explicit RectangleUnion(const std::vector<Box>& boxes);

  /// Calls f(polygon inside box, sign) for every signed box that overlaps
  /// `polygon`; the signed sum of any additive integral over those pieces is
  /// its integral over polygon & union.
  template <typename F>
  void ForEachPiece(const ConvexPolygon& polygon, F&& f) const {
    for (const auto& [box, sign] : signed_boxes_) {
      const ConvexPolygon piece = polygon.ClippedToBox(box.min_m, box.max_m);
      if (!piece.empty()) f(piece, sign);
    }
  }

  /// Area of polygon & union, m^2.
  double Area(const ConvexPolygon& polygon) const;
  /// First moment of polygon & union, m^3.
  Eigen::Vector2d FirstMoment(const ConvexPolygon& polygon) const;
  /// Second moment of polygon & union about `point`, m^4.
  double SecondMoment(const ConvexPolygon& polygon, const Eigen::Vector2d& point) const;

  bool empty() const { return signed_boxes_.empty(); }

 private:
  std::vector<std::pair<Box, double>> signed_boxes_;
};

}  // namespace dream::agents
