#pragma once

#include <string>

namespace dream::world {

// How InitialPoseGenerator spreads robots over the arena.
struct InitialPoseParams {
  // Minimum distance between robot centres. Must exceed collision diameter +
  // 2 * collision offset (0.185 m on the Robotarium) so no pair collides
  // whatever the headings. 0.25 m still fits the simulator's maximum of 50
  // robots in the Robotarium by random placement (it tops out near 70: a
  // sim_only run of more lists its poses); 0.3 m tops out near 45.
  double min_spacing_m = 0.25;
  // Minimum distance from each robot centre to the arena walls.
  double wall_margin_m = 0.1;
  // Rejection sampling gives up after num_robots * this many candidates.
  int max_attempts_per_robot = 1000;

  bool IsValid(std::string* error) const;
};

}  // namespace dream::world
