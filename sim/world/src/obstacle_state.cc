#include "dream/world/obstacle_state.h"

#include <algorithm>
#include <cmath>

namespace dream::world {

bool ObstacleState::IntersectsDisc(double disc_x_m, double disc_y_m, double radius_m) const {
  const double gap_x_m = std::max(std::abs(disc_x_m - center_x_m) - width_m / 2.0, 0.0);
  const double gap_y_m = std::max(std::abs(disc_y_m - center_y_m) - height_m / 2.0, 0.0);
  return gap_x_m * gap_x_m + gap_y_m * gap_y_m <= radius_m * radius_m;
}

}  // namespace dream::world
