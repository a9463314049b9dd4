#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "dream/world/obstacle_path.h"

namespace dream::world {

// A virtual axis-aligned rectangular obstacle as configured. Static when it
// has no path.
struct RectangleObstacleSpec {
  int id = 0;
  Eigen::Vector2d center_m = Eigen::Vector2d::Zero();
  double width_m = 0.0;   // extent along x
  double height_m = 0.0;  // extent along y
  std::optional<ObstaclePath> path;

  // Finite centre, positive finite size; a path needs >= 1 finite waypoint, a
  // positive finite speed and a non-zero length (zero-length legs, e.g. a last
  // waypoint equal to the centre in loop mode, are allowed and skipped).
  bool IsValid(std::string* error) const;
};

}  // namespace dream::world
