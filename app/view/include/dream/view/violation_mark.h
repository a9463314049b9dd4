#pragma once

#include <cstdint>
#include <limits>

#include "dream/world/located_violation.h"

namespace dream::view {

/// One violation of the Robotarium's rules, located: what the page flashes
/// where and when it happened.
struct ViolationMark {
  /// boundary, collision (centres moved 0.025 m forward <= 0.135 m apart) or
  /// obstacle: the kinds summary.json's violations_located names too.
  using Kind = world::LocatedViolation::Kind;
  Kind kind = Kind::kBoundary;
  int64_t step = 0;  ///< the step whose poses broke the rule
  int robot = 0;     ///< the robot (the smaller id of a colliding pair)
  int other = -1;    ///< the pair's other robot, or the obstacle's id; -1 for the boundary
  double x_m = 0.0;  ///< where: the robot, or the middle of a colliding pair
  double y_m = 0.0;
  /// How bad at this step (world::LocatedViolation::worst_m): metres outside,
  /// the pair's collision centres apart, or the overlap with the obstacle.
  double worst_m = std::numeric_limits<double>::quiet_NaN();
};

/// "boundary", "collision", "obstacle": the name the page shows.
const char* ViolationKindName(ViolationMark::Kind kind);

}  // namespace dream::view
