#pragma once

#include <vector>

#include <Eigen/Core>

namespace dream::world {

// How a moving obstacle repeats its path.
enum class ObstaclePathMode {
  // centre -> waypoints[0] -> ... -> waypoints[n-1] -> centre -> ...
  kLoop,
  // centre -> waypoints[0] -> ... -> waypoints[n-1] -> ... -> waypoints[0] -> centre -> ...
  kPingPong,
};

// The route of a moving obstacle. The path starts at the obstacle's initial
// centre, so the centre is its first vertex.
struct ObstaclePath {
  std::vector<Eigen::Vector2d> waypoints_m;
  double speed_mps = 0.0;
  ObstaclePathMode mode = ObstaclePathMode::kLoop;
};

}  // namespace dream::world
