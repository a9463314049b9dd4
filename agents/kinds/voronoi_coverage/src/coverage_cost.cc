#include "dream/voronoi_coverage/coverage_cost.h"

#include "dream/agents/geometry/convex_polygon.h"
#include "dream/agents/geometry/half_plane.h"
#include "dream/agents/geometry/rectangle_union.h"

namespace dream::voronoi_coverage {

CoverageCost::CoverageCost(const Eigen::Vector2d& arena_min_m, const Eigen::Vector2d& arena_max_m)
    : arena_min_m_(arena_min_m), arena_max_m_(arena_max_m) {}

double CoverageCost::Evaluate(const std::vector<Eigen::Vector2d>& positions_m,
                              const std::vector<agents::ObstacleView>& obstacles) const {
  std::vector<agents::RectangleUnion::Box> boxes;
  for (const agents::ObstacleView& obstacle : obstacles) {
    // Only the part inside the arena is taken out of it.
    boxes.push_back({(obstacle.center_m - obstacle.size_m / 2.0).cwiseMax(arena_min_m_),
                     (obstacle.center_m + obstacle.size_m / 2.0).cwiseMin(arena_max_m_)});
  }
  const agents::RectangleUnion blocked(boxes);
  const agents::ConvexPolygon arena = agents::ConvexPolygon::Rectangle(arena_min_m_, arena_max_m_);
  double cost = 0.0;
  for (size_t i = 0; i < positions_m.size(); ++i) {
    const Eigen::Vector2d& p = positions_m[i];
    // Robots at one point (closer than Bisector can separate) count once.
    bool duplicate = false;
    for (size_t j = 0; j < i && !duplicate; ++j) duplicate = !((positions_m[j] - p).norm() > 1e-12);
    if (duplicate) continue;
    agents::ConvexPolygon cell = arena;
    for (size_t j = 0; j < positions_m.size() && !cell.vertices().empty(); ++j) {
      if (j == i) continue;
      if (auto plane = agents::HalfPlane::Bisector(p, positions_m[j], 0.0)) cell.Clip(*plane);
    }
    if (cell.empty()) continue;
    cost += cell.SecondMoment(p) - blocked.SecondMoment(cell, p);
  }
  return cost;
}

}  // namespace dream::voronoi_coverage
