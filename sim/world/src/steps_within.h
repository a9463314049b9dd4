#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

namespace dream::world {

// Largest n with n * dt <= seconds: how many steps a rule stated as "after
// more than `seconds`" lets pass (the command timeout, the firmware's brake,
// the tracker's drop). Computed with the same product the rule is stated in,
// so the boundary step is exactly the documented one; INT64_MAX when
// `seconds` is infinite.
inline int64_t StepsWithin(double time_step_s, double seconds) {
  if (std::isinf(seconds)) return std::numeric_limits<int64_t>::max();
  auto n = static_cast<int64_t>(std::floor(seconds / time_step_s));
  while (static_cast<double>(n + 1) * time_step_s <= seconds) ++n;
  while (n > 0 && static_cast<double>(n) * time_step_s > seconds) --n;
  return n;
}

}  // namespace dream::world
