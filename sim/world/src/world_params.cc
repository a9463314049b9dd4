#include "dream/world/world_params.h"

#include <cmath>

#include "field_check.h"

namespace dream::world {

using field_check::Fail;
using field_check::IsNonNegativeFinite;
using field_check::IsPositiveFinite;

bool WorldParams::IsValid(std::string* error) const {
  if (!arena.IsValid(error)) return false;
  if (!IsPositiveFinite(time_step_s) || time_step_s > 1.0) {
    return Fail(error, "time_step_s", time_step_s, "(0, 1] s");
  }
  if (!IsPositiveFinite(wheel_radius_m)) {
    return Fail(error, "wheel_radius_m", wheel_radius_m, "> 0 m, finite");
  }
  if (!IsPositiveFinite(base_length_m)) {
    return Fail(error, "base_length_m", base_length_m, "> 0 m, finite");
  }
  if (!IsPositiveFinite(max_wheel_speed_radps)) {
    return Fail(error, "max_wheel_speed_radps", max_wheel_speed_radps, "> 0 rad/s, finite");
  }
  if (!IsPositiveFinite(collision_diameter_m)) {
    return Fail(error, "collision_diameter_m", collision_diameter_m, "> 0 m, finite");
  }
  if (!IsNonNegativeFinite(collision_offset_m)) {
    return Fail(error, "collision_offset_m", collision_offset_m, ">= 0 m, finite");
  }
  if (std::isnan(command_timeout_s) || command_timeout_s <= 0.0) {
    return Fail(error, "command_timeout_s", command_timeout_s, "> 0 s (+inf disables the timeout)");
  }
  return true;
}

}  // namespace dream::world
