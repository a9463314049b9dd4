#pragma once

#include <cstdint>
#include <vector>

#include "dream/world/realism_params.h"

namespace dream::world {

// How one real robot departs from its nominal kinematics: its speed per unit
// commanded and its heading drift while its wheels turn (world.realism's
// linear_gain_*, angular_gain_*, heading_drift_*).
struct RobotTraits {
  double linear_gain = 1.0;
  double angular_gain = 1.0;
  double heading_drift_radps = 0.0;

  // One robot's traits per robot, drawn from `seed` (its own random stream, so
  // the other models' draws do not move): Gaussian around each mean with its
  // spread, gains clamped to [kMinGain, kMaxGain] and drift to +-1 rad/s.
  // With zero spreads every robot gets the means and nothing is drawn.
  static std::vector<RobotTraits> Draw(const RealismParams& realism, uint64_t seed, int num_robots);
};

}  // namespace dream::world
