#pragma once

#include <string>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::world {

// The rectangular testbed. Defaults are the Robotarium's.
struct Arena {
  double x_min_m = robotarium::RobotariumConstants::kArenaXMinMeters;
  double x_max_m = robotarium::RobotariumConstants::kArenaXMaxMeters;
  double y_min_m = robotarium::RobotariumConstants::kArenaYMinMeters;
  double y_max_m = robotarium::RobotariumConstants::kArenaYMaxMeters;

  // Like the Robotarium's boundary check: a point exactly on an edge is
  // inside; it is outside iff x < x_min || x > x_max || y < y_min || y > y_max.
  bool Contains(double x_m, double y_m) const {
    return !(x_m < x_min_m || x_m > x_max_m || y_m < y_min_m || y_m > y_max_m);
  }

  double width_m() const { return x_max_m - x_min_m; }
  double height_m() const { return y_max_m - y_min_m; }

  // Bounds finite and x_min < x_max, y_min < y_max.
  bool IsValid(std::string* error) const;
};

}  // namespace dream::world
