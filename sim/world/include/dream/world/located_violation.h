#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace dream::world {

/// One violation of the Robotarium's rules, placed: what pictures mark and
/// summary.json's violations_located lists. Consecutive steps of the same
/// violation by the same robots (or robot and obstacle) are one entry.
struct LocatedViolation {
  enum class Kind {
    kBoundary,   ///< a robot strictly outside the arena
    kCollision,  ///< two robots too close (the Robotarium's collision rule)
    kObstacle,   ///< a robot overlapping a virtual obstacle
  };
  Kind kind = Kind::kBoundary;
  int robot = 0;           ///< the robot (the smaller id of a colliding pair)
  int other = -1;          ///< the pair's other robot, or the obstacle's id; -1 for the boundary
  int64_t first_step = 0;  ///< the first step whose poses broke the rule
  int64_t last_step = 0;   ///< the last step of the uninterrupted stretch
  double x_m = 0.0;        ///< where, at first_step: the robot, or the middle of a colliding pair
  double y_m = 0.0;
  /// How bad it got over the episode, in metres: how far outside the arena
  /// (boundary, largest), how close the pair's collision centres came
  /// (collision, smallest), how deep the collision disc overlapped the
  /// obstacle (obstacle, largest). NaN when it could not be measured.
  double worst_m = std::numeric_limits<double>::quiet_NaN();

  /// Whether `value_m` is worse than `worst_m` for this kind (smaller for a collision).
  bool IsWorse(double value_m) const;
};

/// "boundary", "collision", "obstacle".
const char* LocatedViolationKindName(LocatedViolation::Kind kind);

/// A run's located violations, bounded: the first `listed` in order of their
/// first step, and how many more there were.
struct LocatedViolations {
  std::vector<LocatedViolation> listed;
  int64_t unlisted = 0;  ///< entries found past the bound (not in `listed`)
  int64_t total() const { return static_cast<int64_t>(listed.size()) + unlisted; }
};

}  // namespace dream::world
