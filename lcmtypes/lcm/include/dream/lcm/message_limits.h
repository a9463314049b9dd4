#pragma once

#include <cstdint>

namespace dream::lcm {

/// The largest counts and strings a dream message may carry. Anything larger
/// is refused before it is decoded, so no message can make a receiver
/// allocate more than a few hundred kilobytes.
struct MessageLimits {
  /// Robots in a run: the Robotarium simulator's 50 (a test checks the config agrees).
  static constexpr int32_t kRobots = 50;
  /// Obstacles in a run (520 KB of DREAM_OBSTACLES at most).
  static constexpr int32_t kObstacles = 10000;
  /// Bytes of one radio payload; real ones are tens of bytes.
  static constexpr int32_t kRadioPayloadBytes = 65536;
  /// Bytes of a status or fault detail string.
  static constexpr int32_t kDetailBytes = 65536;
};

}  // namespace dream::lcm
