#include "dream/world/rectangle_obstacle_spec.h"

#include <cmath>

#include "field_check.h"

namespace dream::world {

using field_check::Fail;
using field_check::IsPositiveFinite;

bool RectangleObstacleSpec::IsValid(std::string* error) const {
  const std::string prefix = "rectangle_obstacle[id=" + std::to_string(id) + "].";
  if (!std::isfinite(center_m.x())) return Fail(error, prefix + "center_m.x", center_m.x(), "finite metres");
  if (!std::isfinite(center_m.y())) return Fail(error, prefix + "center_m.y", center_m.y(), "finite metres");
  if (!IsPositiveFinite(width_m)) return Fail(error, prefix + "width_m", width_m, "> 0 m, finite");
  if (!IsPositiveFinite(height_m)) return Fail(error, prefix + "height_m", height_m, "> 0 m, finite");
  if (!path.has_value()) return true;

  if (path->waypoints_m.empty()) {
    return field_check::FailWithText(error,
                                     prefix +
                                         "path.waypoints_m is empty; a moving obstacle needs at least one waypoint "
                                         "(omit the path for a static obstacle)");
  }
  if (!IsPositiveFinite(path->speed_mps)) {
    return Fail(error, prefix + "path.speed_mps", path->speed_mps, "> 0 m/s, finite");
  }
  double path_length_m = 0.0;
  Eigen::Vector2d previous = center_m;
  for (std::size_t i = 0; i < path->waypoints_m.size(); ++i) {
    const Eigen::Vector2d& waypoint = path->waypoints_m[i];
    const std::string field = prefix + "path.waypoints_m[" + std::to_string(i) + "]";
    if (!std::isfinite(waypoint.x())) return Fail(error, field + ".x", waypoint.x(), "finite metres");
    if (!std::isfinite(waypoint.y())) return Fail(error, field + ".y", waypoint.y(), "finite metres");
    path_length_m += (waypoint - previous).norm();
    previous = waypoint;
  }
  if (path_length_m <= 0.0) {
    return field_check::FailWithText(error,
                                     prefix +
                                         "path has zero length (every waypoint equals the centre); allowed: a path "
                                         "that moves, or no path for a static obstacle");
  }
  return true;
}

}  // namespace dream::world
