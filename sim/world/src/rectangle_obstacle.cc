#include "dream/world/rectangle_obstacle.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

#include "field_check.h"

namespace dream::world {

RectangleObstacle::RectangleObstacle(const RectangleObstacleSpec& spec) : spec_(spec), center_m_(spec.center_m) {
  field_check::Checked("RectangleObstacle", spec);
  if (!spec.path.has_value()) return;

  // Turn either mode into one closed cycle of legs, skipping zero-length legs.
  std::vector<Eigen::Vector2d> vertices;
  vertices.push_back(spec.center_m);
  for (const Eigen::Vector2d& waypoint : spec.path->waypoints_m) vertices.push_back(waypoint);
  std::vector<Eigen::Vector2d> cycle = vertices;
  if (spec.path->mode == ObstaclePathMode::kPingPong) {
    for (std::size_t i = vertices.size() - 1; i-- > 0;) cycle.push_back(vertices[i]);
  } else {
    cycle.push_back(vertices.front());
  }
  for (std::size_t i = 0; i + 1 < cycle.size(); ++i) {
    const Eigen::Vector2d delta = cycle[i + 1] - cycle[i];
    const double length_m = delta.norm();
    if (length_m <= 0.0) continue;
    legs_.push_back(Leg{cycle[i], cycle[i + 1], delta / length_m, length_m});
    cycle_length_m_ += length_m;
  }
}

Eigen::Vector2d RectangleObstacle::velocity_mps() const {
  if (legs_.empty()) return Eigen::Vector2d::Zero();
  return legs_[leg_index_].direction * spec_.path->speed_mps;
}

void RectangleObstacle::Advance(double time_step_s) {
  if (legs_.empty()) return;
  // Whole laps change nothing; dropping them bounds the loop below.
  double remaining_m = std::fmod(spec_.path->speed_mps * time_step_s, cycle_length_m_);
  // Arriving exactly at a corner moves onto the next leg, so velocity_mps()
  // always reports the leg the next Advance will follow.
  while (remaining_m >= legs_[leg_index_].length_m - distance_along_leg_m_) {
    remaining_m -= legs_[leg_index_].length_m - distance_along_leg_m_;
    leg_index_ = (leg_index_ + 1) % legs_.size();
    distance_along_leg_m_ = 0.0;
    if (remaining_m <= 0.0) break;
  }
  distance_along_leg_m_ += std::max(remaining_m, 0.0);
  const Leg& leg = legs_[leg_index_];
  center_m_ =
      distance_along_leg_m_ == 0.0 ? leg.start_m : Eigen::Vector2d(leg.start_m + leg.direction * distance_along_leg_m_);
}

ObstacleState RectangleObstacle::State() const {
  const Eigen::Vector2d velocity = velocity_mps();
  return {spec_.id, center_m_.x(), center_m_.y(), spec_.width_m, spec_.height_m, velocity.x(), velocity.y()};
}

bool RectangleObstacle::IntersectsDisc(double center_x_m, double center_y_m, double radius_m) const {
  // The velocity plays no part: leave it zero rather than work out the leg.
  const ObstacleState here{spec_.id, center_m_.x(), center_m_.y(), spec_.width_m, spec_.height_m};
  return here.IntersectsDisc(center_x_m, center_y_m, radius_m);
}

std::vector<RectangleObstacle> RectangleObstacle::BuildAll(const std::vector<RectangleObstacleSpec>& specs,
                                                           const std::string& owner, const std::string& field) {
  std::vector<RectangleObstacle> obstacles;
  obstacles.reserve(specs.size());
  std::set<int> ids;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const std::string where = owner + ": " + field + "[" + std::to_string(i) + "]";
    std::string error;
    if (!specs[i].IsValid(&error)) throw std::invalid_argument(where + ": " + error);
    if (!ids.insert(specs[i].id).second) {
      throw std::invalid_argument(where + ".id = " + std::to_string(specs[i].id) +
                                  " is used by an earlier obstacle; ids must be unique");
    }
    obstacles.emplace_back(specs[i]);
  }
  return obstacles;
}

}  // namespace dream::world
