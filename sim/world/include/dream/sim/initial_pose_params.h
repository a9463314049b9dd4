#pragma once

#include <string>

namespace dream::sim {

// How InitialPoseGenerator spreads robots over the arena.
struct InitialPoseParams {
  // Minimum distance between robot centres. Must exceed collision diameter +
  // 2 * collision offset (0.185 m on the Robotarium) so no pair collides
  // whatever the headings.
  double min_spacing_m = 0.3;
  // Minimum distance from each robot centre to the arena walls.
  double wall_margin_m = 0.1;
  // Rejection sampling gives up after num_robots * this many candidates.
  int max_attempts_per_robot = 1000;

  bool IsValid(std::string* error) const;
};

}  // namespace dream::sim
