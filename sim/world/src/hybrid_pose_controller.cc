#include "dream/world/hybrid_pose_controller.h"

#include <cmath>

namespace dream::world {

namespace {

constexpr double kHalfPi = 1.5707963267948966;

}  // namespace

void HybridPoseController::Apply(const std::vector<Pose2>& states, const std::vector<Pose2>& goals,
                                 std::vector<UnicycleCommand>* commands) {
  if (approaching_.size() != states.size()) approaching_.assign(states.size(), 1);
  commands->resize(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) (*commands)[i] = Command(states[i], goals[i], &approaching_[i]);
}

UnicycleCommand HybridPoseController::ApplyOne(const Pose2& state, const Pose2& goal) {
  if (approaching_.size() != 1) approaching_.assign(1, 1);
  return Command(state, goal, &approaching_[0]);
}

UnicycleCommand HybridPoseController::Command(const Pose2& state, const Pose2& goal, char* approaching) const {
  double dx = goal.x_m - state.x_m;
  double dy = goal.y_m - state.y_m;
  const double distance_m = std::sqrt(dx * dx + dy * dy);  // as numpy's norm
  const double heading_error = goal.theta_rad - state.theta_rad;
  const double wrapped_error = std::atan2(std::sin(heading_error), std::cos(heading_error));
  if (*approaching && distance_m > gains_.position_error_m - gains_.position_epsilon_m) {
    if (distance_m > gains_.velocity_magnitude_limit_mps) {
      dx = gains_.velocity_magnitude_limit_mps * dx / distance_m;
      dy = gains_.velocity_magnitude_limit_mps * dy / distance_m;
    }
    // rps's si_to_uni: v along the heading, w from the angle to the wanted velocity.
    const double c = std::cos(state.theta_rad);
    const double s = std::sin(state.theta_rad);
    const double forward = c * dx + s * dy;
    const double left = -s * dx + c * dy;
    return UnicycleCommand{gains_.linear_velocity_gain * forward,
                           gains_.angular_velocity_limit_radps * std::atan2(left, forward) / kHalfPi};
  }
  if (std::abs(wrapped_error) > gains_.rotation_error_rad) {
    *approaching = distance_m > gains_.position_error_m ? 1 : 0;
    return UnicycleCommand{0.0, 2.0 * wrapped_error};
  }
  return UnicycleCommand{};
}

}  // namespace dream::world
