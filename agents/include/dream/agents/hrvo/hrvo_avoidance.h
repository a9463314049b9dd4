#pragma once

#include <Eigen/Core>
#include <vector>

#include "dream/agents/hrvo/hrvo_neighbour.h"

namespace dream::agents {

/// Reciprocal collision avoidance for a single-integrator robot: given what
/// it knows of itself and its neighbours, the safe planar velocity closest to
/// the one it would like. Implementations: HrvoThesis (the thesis's sampled
/// search, ported faithfully) and HrvoExact (the exact closest safe velocity).
///
/// Pure logic: plain values in, plain values out, world frame throughout.
/// Implementations keep only scratch memory between calls (SafeVelocity is
/// non-const so it can reuse it); one instance per robot.
class HrvoAvoidance {
 public:
  virtual ~HrvoAvoidance() = default;

  /// @param position_m own centre (the arena-boundary check uses it).
  /// @param current_velocity_mps own velocity now: pass the previous call's
  ///        result, as the thesis does (HRVO's reciprocal apex and its choice
  ///        of side depend on it). Zero at start.
  /// @param preferred_velocity_mps where the robot's task wants it to go.
  /// @param neighbours the robots it can sense (its movement sensor's range).
  /// @return a velocity of norm <= max speed.
  virtual Eigen::Vector2d SafeVelocity(const Eigen::Vector2d& position_m, const Eigen::Vector2d& current_velocity_mps,
                                       const Eigen::Vector2d& preferred_velocity_mps,
                                       const std::vector<HrvoNeighbour>& neighbours) = 0;
};

}  // namespace dream::agents
