#include "dream/agents/geometry/rectangle_union.h"

#include <functional>

namespace dream::agents {
namespace {

bool Empty(const RectangleUnion::Box& box) { return !(box.min_m.x() < box.max_m.x() && box.min_m.y() < box.max_m.y()); }

RectangleUnion::Box Intersect(const RectangleUnion::Box& a, const RectangleUnion::Box& b) {
  return {a.min_m.cwiseMax(b.min_m), a.max_m.cwiseMin(b.max_m)};
}

}  // namespace

RectangleUnion::RectangleUnion(const std::vector<Box>& boxes_in) {
  std::vector<Box> boxes;
  for (const Box& box : boxes_in) {
    if (!Empty(box) && box.min_m.allFinite() && box.max_m.allFinite()) boxes.push_back(box);
  }
  // Every subset's intersection with sign (-1)^(size + 1). Supersets of an
  // empty intersection are empty, so the search stops there: disjoint
  // obstacles cost one entry each.
  const std::function<void(size_t, const Box*, double)> add = [&](size_t next, const Box* so_far, double sign) {
    for (size_t k = next; k < boxes.size(); ++k) {
      const Box both = so_far == nullptr ? boxes[k] : Intersect(*so_far, boxes[k]);
      if (Empty(both)) continue;
      signed_boxes_.emplace_back(both, sign);
      add(k + 1, &both, -sign);
    }
  };
  add(0, nullptr, 1.0);
}

double RectangleUnion::Area(const ConvexPolygon& polygon) const {
  double area = 0.0;
  ForEachPiece(polygon, [&](const ConvexPolygon& piece, double sign) { area += sign * piece.Area(); });
  return area;
}

Eigen::Vector2d RectangleUnion::FirstMoment(const ConvexPolygon& polygon) const {
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  ForEachPiece(polygon, [&](const ConvexPolygon& piece, double sign) { moment += sign * piece.FirstMoment(); });
  return moment;
}

double RectangleUnion::SecondMoment(const ConvexPolygon& polygon, const Eigen::Vector2d& point) const {
  double moment = 0.0;
  ForEachPiece(polygon, [&](const ConvexPolygon& piece, double sign) { moment += sign * piece.SecondMoment(point); });
  return moment;
}

}  // namespace dream::agents
