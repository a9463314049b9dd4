#include "dream/agents/geometry/single_integrator_to_unicycle.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dream::agents {

SingleIntegratorToUnicycle::SingleIntegratorToUnicycle(double linear_gain, double angular_limit_radps)
    : linear_gain_(linear_gain), angular_limit_radps_(angular_limit_radps) {
  if (!(linear_gain > 0.0) || !std::isfinite(linear_gain)) {
    throw std::invalid_argument("linear_gain must be positive, got " + std::to_string(linear_gain));
  }
  if (!(angular_limit_radps >= 0.0) || !std::isfinite(angular_limit_radps)) {
    throw std::invalid_argument("angular_limit_radps must be >= 0, got " + std::to_string(angular_limit_radps));
  }
}

UnicycleCommand SingleIntegratorToUnicycle::Map(const Eigen::Vector2d& velocity_world_mps, double theta_rad) const {
  const Eigen::Vector2d forward(std::cos(theta_rad), std::sin(theta_rad));
  const Eigen::Vector2d left(-std::sin(theta_rad), std::cos(theta_rad));
  const double along = forward.dot(velocity_world_mps);
  const double across = left.dot(velocity_world_mps);
  return {linear_gain_ * along, angular_limit_radps_ * std::atan2(across, along) / (M_PI / 2.0)};
}

}  // namespace dream::agents
