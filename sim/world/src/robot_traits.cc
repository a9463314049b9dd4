#include "dream/world/robot_traits.h"

#include <algorithm>

#include "realism_random.h"

namespace dream::world {

std::vector<RobotTraits> RobotTraits::Draw(const RealismParams& realism, uint64_t seed, int num_robots) {
  std::vector<RobotTraits> traits(static_cast<size_t>(std::max(num_robots, 0)));
  RealismRandom random(seed, RealismStream::kRobotTraits);
  for (RobotTraits& robot : traits) {
    // Three draws per robot whatever the spreads, so robot i's traits do not
    // depend on which spreads are zero.
    const double linear = random.Gaussian();
    const double angular = random.Gaussian();
    const double drift = random.Gaussian();
    robot.linear_gain = std::clamp(realism.linear_gain_mean + realism.linear_gain_spread * linear,
                                   RealismParams::kMinGain, RealismParams::kMaxGain);
    robot.angular_gain = std::clamp(realism.angular_gain_mean + realism.angular_gain_spread * angular,
                                    RealismParams::kMinGain, RealismParams::kMaxGain);
    robot.heading_drift_radps =
        std::clamp(realism.heading_drift_mean_radps + realism.heading_drift_spread_radps * drift, -1.0, 1.0);
  }
  return traits;
}

}  // namespace dream::world
