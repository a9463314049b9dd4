#pragma once

#include <Eigen/Core>

#include "dream/agents/hrvo_neighbour.h"

namespace dream::agents {

/// A velocity obstacle: the open wedge of own velocities v with
///   Cross(right_leg, v - apex) > 0  and  Cross(left_leg, v - apex) < 0,
/// i.e. the directions strictly between the two legs as seen from the apex.
/// When the robots already overlap the legs are opposite and the wedge is a
/// half-plane.
struct HrvoCone {
  Eigen::Vector2d apex_mps = Eigen::Vector2d::Zero();
  Eigen::Vector2d right_leg = Eigen::Vector2d::UnitX();  ///< unit, clockwise edge
  Eigen::Vector2d left_leg = Eigen::Vector2d::UnitX();   ///< unit, counter-clockwise edge

  /// The plain velocity obstacle: own velocities that collide within any
  /// time with a neighbour at `relative_position_m` moving at `apex_mps`
  /// (legs at +/- asin(R / d) about the bearing; a half-plane when d <= R).
  static HrvoCone Velocity(const Eigen::Vector2d& relative_position_m, const Eigen::Vector2d& apex_mps,
                           double combined_radius_m);

  /// The hybrid reciprocal velocity obstacle (Snape et al. 2011): the leg on
  /// the side own velocity already passes on is the reciprocal one (apex
  /// shifted to the mean of both velocities, so each robot takes half the
  /// avoidance), the other leg stays that of the plain VO (crossing over to
  /// the other side costs the whole avoidance). Both robots of a pair judge the
  /// side from the same relative velocity, so they pick the same side; an
  /// exact tie counts as the right side. Overlapping robots get the reciprocal
  /// half-plane: no approaching faster than the mean velocity.
  static HrvoCone Hybrid(const HrvoNeighbour& neighbour, const Eigen::Vector2d& own_velocity_mps,
                         double combined_radius_m);

  /// True when v is inside the open wedge by more than `tolerance` (m/s) from
  /// each leg's line.
  bool Contains(const Eigen::Vector2d& velocity_mps, double tolerance = 0.0) const;

  /// Distance from v to the nearest point outside the wedge, m/s; 0 outside.
  double Penetration(const Eigen::Vector2d& velocity_mps) const;
};

/// z-component of the 2-D cross product: positive when b is counter-clockwise of a.
inline double Cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace dream::agents
