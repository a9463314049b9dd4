#pragma once

#include <cmath>

#include "dream/world/unicycle_command.h"
#include "dream/world/wheel_speeds.h"

namespace dream::world {

// Unicycle <-> differential-drive conversions and wheel saturation, written
// with the same operations in the same order as the Robotarium V2 simulator
// (_uni_to_diff, _diff_to_uni, _threshold), so results are bit-identical to
// it as long as the compiler does not fuse multiply-adds (dream_world builds
// with -ffp-contract=off).

// left = (2v - L w) / (2r), right = (2v + L w) / (2r).
inline WheelSpeeds UnicycleToWheelSpeeds(const UnicycleCommand& command, double wheel_radius_m, double base_length_m) {
  const double inverse_two_radius = 1.0 / (2.0 * wheel_radius_m);
  return WheelSpeeds{inverse_two_radius * (2.0 * command.v_mps - base_length_m * command.w_radps),
                     inverse_two_radius * (2.0 * command.v_mps + base_length_m * command.w_radps)};
}

// v = r/2 (left + right), w = r/L (right - left).
inline UnicycleCommand WheelSpeedsToUnicycle(const WheelSpeeds& wheels, double wheel_radius_m, double base_length_m) {
  return UnicycleCommand{(wheel_radius_m / 2.0) * (wheels.left_radps + wheels.right_radps),
                         (wheel_radius_m / base_length_m) * (wheels.right_radps - wheels.left_radps)};
}

// True if either wheel turns faster than the limit (strictly).
inline bool ExceedsWheelSpeedLimit(const WheelSpeeds& wheels, double max_wheel_speed_radps) {
  return std::abs(wheels.left_radps) > max_wheel_speed_radps || std::abs(wheels.right_radps) > max_wheel_speed_radps;
}

// Clips each wheel to +-max independently (this changes the direction of
// travel when only one wheel saturates, exactly as on the Robotarium).
inline WheelSpeeds ClipWheelSpeeds(const WheelSpeeds& wheels, double max_wheel_speed_radps) {
  auto clip = [max_wheel_speed_radps](double speed_radps) {
    if (std::abs(speed_radps) > max_wheel_speed_radps) {
      return speed_radps > 0.0 ? max_wheel_speed_radps : -max_wheel_speed_radps;
    }
    return speed_radps;
  };
  return WheelSpeeds{clip(wheels.left_radps), clip(wheels.right_radps)};
}

// The Robotarium's _threshold: uni->diff, clip, diff->uni. Note that even an
// in-limit command comes back changed by rounding (the round trip is not
// exact); the official simulator stores this result as the held velocity.
inline UnicycleCommand SaturateUnicycleCommand(const UnicycleCommand& command, double wheel_radius_m,
                                               double base_length_m, double max_wheel_speed_radps) {
  return WheelSpeedsToUnicycle(
      ClipWheelSpeeds(UnicycleToWheelSpeeds(command, wheel_radius_m, base_length_m), max_wheel_speed_radps),
      wheel_radius_m, base_length_m);
}

}  // namespace dream::world
