#include "dream/agents/geometry/reversible_si_to_uni.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dream::agents {

ReversibleSiToUni::ReversibleSiToUni(double linear_gain, double angular_gain, double hysteresis_rad)
    : linear_gain_(linear_gain), angular_gain_(angular_gain), hysteresis_rad_(hysteresis_rad) {
  if (!(linear_gain > 0.0) || !std::isfinite(linear_gain)) {
    throw std::invalid_argument("linear_gain must be > 0, got " + std::to_string(linear_gain));
  }
  if (!(angular_gain > 0.0) || !std::isfinite(angular_gain)) {
    throw std::invalid_argument("angular_gain must be > 0, got " + std::to_string(angular_gain));
  }
  if (!(hysteresis_rad >= 0.0 && hysteresis_rad < M_PI / 2.0)) {
    throw std::invalid_argument("hysteresis_rad must be in [0, pi/2), got " + std::to_string(hysteresis_rad));
  }
}

UnicycleCommand ReversibleSiToUni::Map(const Eigen::Vector2d& velocity_world_mps, double theta_rad) {
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  const double along = c * velocity_world_mps.x() + s * velocity_world_mps.y();
  const double across = -s * velocity_world_mps.x() + c * velocity_world_mps.y();
  if (along == 0.0 && across == 0.0) return {};
  // Angle from the driving direction (heading, or heading + pi) to dxi.
  double error = backward_ ? std::atan2(-across, -along) : std::atan2(across, along);
  if (std::abs(error) > M_PI / 2.0 + hysteresis_rad_) {
    backward_ = !backward_;
    error = error > 0.0 ? error - M_PI : error + M_PI;
  }
  return {linear_gain_ * along, angular_gain_ * error / (M_PI / 2.0)};
}

}  // namespace dream::agents
