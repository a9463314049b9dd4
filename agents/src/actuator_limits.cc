#include "dream/agents/framework/actuator_limits.h"

#include <algorithm>
#include <cmath>

namespace dream::agents {

ActuatorLimits::ActuatorLimits(RobotLimits limits) : limits_(limits) {}

UnicycleCommand ActuatorLimits::Apply(const UnicycleCommand& command) const {
  if (!std::isfinite(command.v_mps) || !std::isfinite(command.w_radps)) return {};
  const double v_max = limits_.max_linear_speed_mps;
  const double w_max = limits_.max_angular_speed_radps;
  double v = std::clamp(command.v_mps, -v_max, v_max);
  const double w = std::clamp(command.w_radps, -w_max, w_max);
  // Fastest wheel: |v|/r + (L/2r)|w| must stay within the wheel limit.
  const double r = limits_.wheel_radius_m;
  const double turn_share = limits_.base_length_m / (2.0 * r) * std::abs(w);
  if (std::abs(v) / r + turn_share > limits_.max_wheel_speed_radps) {
    // A hair inside the limit: exactly at it, the world's own uni->diff
    // arithmetic can land one ulp over and count an actuator warning.
    const double v_allowed = std::max(0.0, (limits_.max_wheel_speed_radps - turn_share) * r * (1.0 - 1e-9));
    v = std::copysign(v_allowed, v);
  }
  return {v, w};
}

}  // namespace dream::agents
