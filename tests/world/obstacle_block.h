#pragma once

#include <Eigen/Core>

#include "dream/world/rectangle_obstacle_spec.h"

namespace dream::world::testing {

/// A static rectangular obstacle centred at (x_m, y_m).
inline RectangleObstacleSpec Block(int id, double x_m, double y_m, double width_m, double height_m) {
  RectangleObstacleSpec spec;
  spec.id = id;
  spec.center_m = Eigen::Vector2d(x_m, y_m);
  spec.width_m = width_m;
  spec.height_m = height_m;
  return spec;
}

}  // namespace dream::world::testing
