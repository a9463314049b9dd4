#pragma once

#include <cstdint>

namespace dream::lcm {

/// The largest counts and strings a dream message may carry. Anything larger
/// is refused before it is decoded, so no message can make a receiver
/// allocate more than a few hundred kilobytes.
struct MessageLimits {
  /// Robots a message may carry: the most a `sim_only: true` run may have
  /// (config::ControllerConfig::kMaxRobotsSimOnly, checked equal in
  /// sim_node.cc; other runs stop at the Robotarium simulator's 50), and what
  /// dream view draws; a robot_poses_t of 128 robots is 5 KiB.
  static constexpr int32_t kRobots = 128;
  /// Obstacles in a run (520 KB of DREAM_OBSTACLES at most).
  static constexpr int32_t kObstacles = 10000;
  /// Bytes of one radio payload; real ones are tens of bytes.
  static constexpr int32_t kRadioPayloadBytes = 65536;
  /// Bytes of a status or fault detail string.
  static constexpr int32_t kDetailBytes = 65536;
};

}  // namespace dream::lcm
