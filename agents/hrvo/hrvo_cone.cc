#include "dream/agents/hrvo/hrvo_cone.h"

#include <algorithm>
#include <cmath>

namespace dream::agents {
namespace {

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

// Unit bearing to the neighbour; coincident robots get an arbitrary one.
Eigen::Vector2d Bearing(const Eigen::Vector2d& relative_position_m) {
  const double distance_m = relative_position_m.norm();
  return distance_m > 1e-12 ? Eigen::Vector2d(relative_position_m / distance_m) : Eigen::Vector2d::UnitX();
}

}  // namespace

HrvoCone HrvoCone::Velocity(const Eigen::Vector2d& relative_position_m, const Eigen::Vector2d& apex_mps,
                            double combined_radius_m) {
  // Legs at +/- asin(R / d) about the bearing, without trigonometry: the
  // bearing rotated by an angle whose sine is R / d. Overlapping (or
  // coincident) robots: sine 1, the wedge opens to a half-plane.
  const double distance_m = relative_position_m.norm();
  const Eigen::Vector2d b = Bearing(relative_position_m);
  const double sine = distance_m > combined_radius_m ? combined_radius_m / distance_m : 1.0;
  const double cosine = std::sqrt(std::max(0.0, 1.0 - sine * sine));
  HrvoCone cone;
  cone.apex_mps = apex_mps;
  cone.right_leg = {cosine * b.x() + sine * b.y(), -sine * b.x() + cosine * b.y()};
  cone.left_leg = {cosine * b.x() - sine * b.y(), sine * b.x() + cosine * b.y()};
  return cone;
}

bool HrvoCone::PassesLeft(const Eigen::Vector2d& relative_position_m, const Eigen::Vector2d& own_velocity_mps,
                          const Eigen::Vector2d& other_velocity_mps) {
  return Cross2(relative_position_m, own_velocity_mps - other_velocity_mps) > 0.0;
}

HrvoCone HrvoCone::Hybrid(const HrvoNeighbour& neighbour, const Eigen::Vector2d& own_velocity_mps,
                          double combined_radius_m, bool pass_left) {
  const Eigen::Vector2d& p = neighbour.relative_position_m;
  const Eigen::Vector2d& v_other = neighbour.velocity_mps;
  const Eigen::Vector2d reciprocal_apex = 0.5 * (own_velocity_mps + v_other);
  HrvoCone cone = Velocity(p, v_other, combined_radius_m);
  if (p.norm() <= combined_radius_m) {
    // Overlapping: neither may approach faster than the mean velocity.
    cone.apex_mps = reciprocal_apex;
    return cone;
  }
  if (pass_left) {
    // Left leg reciprocal, right leg from the plain VO.
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
