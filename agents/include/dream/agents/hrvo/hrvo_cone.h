#pragma once

#include <Eigen/Core>

#include "dream/agents/hrvo/hrvo_neighbour.h"

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

  /// The hybrid reciprocal velocity obstacle (Snape et al. 2011). The leg on
  /// the side the robot passes on is the reciprocal one (apex shifted to the
  /// mean of both velocities, so each robot takes half the avoidance); the
  /// other leg stays that of the plain VO (crossing over costs the whole
  /// avoidance). `pass_left`: the robot passes with the neighbour on its
  /// right (see PassesLeft). Overlapping robots get the reciprocal
  /// half-plane: neither may approach faster than their mean velocity.
  static HrvoCone Hybrid(const HrvoNeighbour& neighbour, const Eigen::Vector2d& own_velocity_mps,
                         double combined_radius_m, bool pass_left);

  /// HRVO's side rule: true when the relative velocity own - other points
  /// counter-clockwise of the bearing (passing on the left). The neighbour,
  /// judging from the same two velocities, gets the same answer, so the pair
  /// pass each other on the same side; an exact tie counts as the right side.
  static bool PassesLeft(const Eigen::Vector2d& relative_position_m, const Eigen::Vector2d& own_velocity_mps,
                         const Eigen::Vector2d& other_velocity_mps);

  /// True when v is inside the open wedge by more than `tolerance` (m/s) from
  /// each leg's line.
  bool Contains(const Eigen::Vector2d& velocity_mps, double tolerance = 0.0) const;

  /// Distance from v to the nearest point outside the wedge, m/s; 0 outside.
  double Penetration(const Eigen::Vector2d& velocity_mps) const;
};

/// z-component of the 2-D cross product: positive when b is counter-clockwise of a.
inline double Cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace dream::agents
