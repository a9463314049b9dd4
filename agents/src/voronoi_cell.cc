#include "dream/agents/geometry/voronoi_cell.h"
#include "dream/agents/fields/field_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/params_check.h"
#include "dream/agents/geometry/rectangle_union.h"

namespace dream::agents {

bool VoronoiCellParams::IsValid(std::string* error) const {
  VoronoiCellParams fields = *this;
  if (!CheckFields(fields, error) || !CheckArena(error, arena_min_m, arena_max_m)) return false;
  if (!(std::isfinite(wall_margin_m) && wall_margin_m >= 0.0) ||
      2.0 * wall_margin_m >= (arena_max_m - arena_min_m).minCoeff()) {
    return FailParams(error,
                      "wall_margin_m must be >= 0 and leave room inside the arena, got " + NumberText(wall_margin_m));
  }
  return true;
}

VoronoiCell::VoronoiCell(const VoronoiCellParams& params_in, const Eigen::Vector2d& self_m,
                         const std::vector<VoronoiNeighbour>& neighbours,
                         const std::vector<Eigen::Vector2d>& obstacle_points_m,
                         const std::vector<ObstacleRectangle>& obstacle_rectangles) {
  const VoronoiCellParams& params = CheckedParams(params_in);
  const ConvexPolygon disc = ConvexPolygon::RegularPolygon(self_m, params.disc_radius_m, params.disc_sides);

  // The coverage region: disc & arena & plain bisectors, minus obstacles.
  ConvexPolygon share = disc.ClippedToBox(params.arena_min_m, params.arena_max_m);
  for (const VoronoiNeighbour& neighbour : neighbours) {
    if (share.vertices().empty()) break;
    if (auto plane = HalfPlane::Bisector(self_m, neighbour.position_m, 0.0)) share.Clip(*plane);
  }
  std::vector<RectangleUnion::Box> boxes;
  for (const ObstacleRectangle& rectangle : obstacle_rectangles) {
    boxes.push_back({rectangle.center_m - rectangle.size_m / 2.0, rectangle.center_m + rectangle.size_m / 2.0});
  }
  const RectangleUnion blocked(boxes);
  coverage_area_m2_ = share.Area() - blocked.Area(share);
  const Eigen::Vector2d first_moment = share.FirstMoment() - blocked.FirstMoment(share);
  // Below a square millimetre the robot has nothing to cover worth moving for.
  coverage_centroid_m_ = coverage_area_m2_ > 1e-6 ? Eigen::Vector2d(first_moment / coverage_area_m2_) : self_m;

  // The cell: walls, buffered bisectors, buffered virtual agents.
  const double margin = params.wall_margin_m;
  constraints_.push_back({Eigen::Vector2d(1.0, 0.0), params.arena_max_m.x() - margin});
  constraints_.push_back({Eigen::Vector2d(-1.0, 0.0), -(params.arena_min_m.x() + margin)});
  constraints_.push_back({Eigen::Vector2d(0.0, 1.0), params.arena_max_m.y() - margin});
  constraints_.push_back({Eigen::Vector2d(0.0, -1.0), -(params.arena_min_m.y() + margin)});
  for (const VoronoiNeighbour& neighbour : neighbours) {
    if (auto plane = HalfPlane::Bisector(self_m, neighbour.position_m,
                                         params.robot_buffer_m + std::max(neighbour.extra_buffer_m, 0.0))) {
      constraints_.push_back(*plane);
    }
  }
  for (const Eigen::Vector2d& closest : obstacle_points_m) {
    // A robot centre on the obstacle has no direction to mirror along; it is
    // in collision already and the other cuts are all it has.
    if (auto plane = HalfPlane::AwayFromObstacle(self_m, closest, params.obstacle_buffer_m)) {
      constraints_.push_back(*plane);
    }
  }
  polygon_ = disc;
  for (const HalfPlane& plane : constraints_) {
    polygon_.Clip(plane);
    if (polygon_.vertices().empty()) break;
  }
  goal_m_ = polygon_.empty() ? self_m : polygon_.ClosestPoint(coverage_centroid_m_);
}

}  // namespace dream::agents
