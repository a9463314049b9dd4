#include "dream/agents/hrvo_cone.h"

#include <algorithm>
#include <cmath>

namespace dream::agents {
namespace {

Eigen::Vector2d Direction(double angle_rad) { return {std::cos(angle_rad), std::sin(angle_rad)}; }

// Distance from w (relative to the apex) to the ray from the apex along unit u.
double DistanceToRay(const Eigen::Vector2d& w, const Eigen::Vector2d& u) {
  return w.dot(u) >= 0.0 ? std::abs(Cross2(u, w)) : w.norm();
}

// Intersection of the lines a + s u and b + t v (not parallel).
Eigen::Vector2d Intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& u, const Eigen::Vector2d& b,
                          const Eigen::Vector2d& v) {
  const double s = Cross2(b - a, v) / Cross2(u, v);
  return a + s * u;
}

}  // namespace

HrvoCone HrvoCone::Velocity(const Eigen::Vector2d& relative_position_m, const Eigen::Vector2d& apex_mps,
                            double combined_radius_m) {
  const double distance_m = relative_position_m.norm();
  const double bearing_rad = std::atan2(relative_position_m.y(), relative_position_m.x());
  // Overlapping (or coincident) robots: the wedge opens to a half-plane.
  const double half_angle_rad =
      distance_m > combined_radius_m ? std::asin(combined_radius_m / distance_m) : M_PI / 2.0;
  HrvoCone cone;
  cone.apex_mps = apex_mps;
  cone.right_leg = Direction(bearing_rad - half_angle_rad);
  cone.left_leg = Direction(bearing_rad + half_angle_rad);
  return cone;
}

HrvoCone HrvoCone::Hybrid(const HrvoNeighbour& neighbour, const Eigen::Vector2d& own_velocity_mps,
                          double combined_radius_m) {
  const Eigen::Vector2d& p = neighbour.relative_position_m;
  const Eigen::Vector2d& v_other = neighbour.velocity_mps;
  const Eigen::Vector2d reciprocal_apex = 0.5 * (own_velocity_mps + v_other);
  HrvoCone cone = Velocity(p, v_other, combined_radius_m);
  if (p.norm() <= combined_radius_m) {
    cone.apex_mps = reciprocal_apex;
    return cone;
  }
  // Own velocity left of the reciprocal centre line <=> the relative velocity
  // is counter-clockwise of the bearing; the pair sees the same sign.
  if (Cross2(p, own_velocity_mps - v_other) > 0.0) {
    // Passing on the left: left leg reciprocal, right leg from the plain VO.
    cone.apex_mps = Intersect(reciprocal_apex, cone.left_leg, v_other, cone.right_leg);
  } else {
    cone.apex_mps = Intersect(reciprocal_apex, cone.right_leg, v_other, cone.left_leg);
  }
  return cone;
}

bool HrvoCone::Contains(const Eigen::Vector2d& velocity_mps, double tolerance) const {
  const Eigen::Vector2d w = velocity_mps - apex_mps;
  return Cross2(right_leg, w) > tolerance && Cross2(left_leg, w) < -tolerance;
}

double HrvoCone::Penetration(const Eigen::Vector2d& velocity_mps) const {
  if (!Contains(velocity_mps)) return 0.0;
  const Eigen::Vector2d w = velocity_mps - apex_mps;
  return std::min(DistanceToRay(w, right_leg), DistanceToRay(w, left_leg));
}

}  // namespace dream::agents
