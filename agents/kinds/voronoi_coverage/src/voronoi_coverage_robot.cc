#include "dream/voronoi_coverage/voronoi_coverage_robot.h"
#include "dream/agents/fields/field_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "dream/agents/framework/position_message.h"
#include "dream/agents/framework/params_check.h"

namespace dream::voronoi_coverage {

bool VoronoiCoverageParams::IsValid(std::string* error) const {
  return cell.IsValid(error) && agents::CheckFields(*this, error) && agents::CheckPositive(error, "step_s", step_s);
}

VoronoiCoverageRobot::VoronoiCoverageRobot(int id, const agents::RobotParams& robot_params,
                                           const VoronoiCoverageParams& params)
    : agents::Robot(id, robot_params), params_(agents::CheckedParams(params)) {}

std::optional<std::vector<uint8_t>> VoronoiCoverageRobot::OnRadio(const std::vector<agents::RadioMessage>& heard) {
  ++radio_rounds_;
  // Only robots heard now are in range; one out of range cannot share a cell
  // border within the disc (the radio reaches 2 R), so forget it.
  std::map<int, Known> neighbours;
  for (const agents::RadioMessage& message : heard) {
    if (message.sender_id == id()) continue;
    const std::optional<agents::PositionMessage> decoded =
        agents::PositionMessage::Decode(message.payload, message.sender_id);
    if (!decoded) {
      CountBadRadioMessage(message);
      const auto previous = neighbours_.find(message.sender_id);
      if (previous != neighbours_.end()) neighbours.insert(*previous);
      continue;
    }
    neighbours[message.sender_id] = Known{decoded->position_m, message.sent_step};
  }
  neighbours_ = std::move(neighbours);
  if (!has_odometry()) return std::nullopt;
  return agents::PositionMessage{id(), pose().head<2>()}.Encode();
}

double VoronoiCoverageRobot::SafeSpeed(double v_mps, const std::vector<agents::HalfPlane>& constraints,
                                       const Eigen::Vector2d& position_m, double heading_rad, double step_s) {
  const Eigen::Vector2d heading(std::cos(heading_rad), std::sin(heading_rad));
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  for (const agents::HalfPlane& plane : constraints) {
    // Moving v for one step changes the slack by -step_s v (n . h); allow
    // using up the slack there is, and none when it is already negative.
    const double rate = step_s * plane.normal.dot(heading);
    if (std::abs(rate) < 1e-15) continue;
    const double room = std::max(plane.Slack(position_m), 0.0);
    if (rate > 0.0) {
      upper = std::min(upper, room / rate);
    } else {
      lower = std::max(lower, room / rate);
    }
  }
  return std::clamp(v_mps, lower, upper);
}

agents::UnicycleCommand VoronoiCoverageRobot::Update(int64_t step) {
  if (!has_odometry() || radio_rounds_ < params_.radio_rounds_before_moving) {
    goal_m_ = pose().head<2>();
    return {};
  }
  const Eigen::Vector2d position = pose().head<2>();
  const double heading = pose().z();
  // The command holds until the next update; expect that to come after as
  // many steps as this one did (1 with the default robot period).
  const int64_t hold_steps = last_update_step_ >= 0 ? std::max<int64_t>(step - last_update_step_, 1) : 1;
  last_update_step_ = step;
  const double horizon_s = params_.step_s * static_cast<double>(hold_steps);
  std::vector<agents::VoronoiNeighbour> neighbours;
  neighbours.reserve(neighbours_.size());
  for (const auto& [neighbour_id, known] : neighbours_) {
    // It may have moved since it spoke, and may move while this command holds.
    const double age_s = params_.step_s * static_cast<double>(std::max<int64_t>(step - known.sent_step, 0));
    neighbours.push_back({known.position_m, params_.max_speed_mps * (age_s + horizon_s)});
  }
  const agents::VoronoiCell cell(params_.cell, position, neighbours, obstacles().closest_points_m,
                                 obstacles().rectangles);

  bool inside = true;
  for (const agents::HalfPlane& plane : cell.constraints()) inside = inside && plane.Contains(position);
  if (!cell.empty()) {
    goal_m_ = cell.goal_m();
  } else {
    // Squeezed out of every feasible point: head back across the violated lines.
    Eigen::Vector2d push = Eigen::Vector2d::Zero();
    for (const agents::HalfPlane& plane : cell.constraints())
      push += std::min(plane.Slack(position), 0.0) * plane.normal;
    goal_m_ = position + push;
  }
  const Eigen::Vector2d error = goal_m_ - position;
  if (inside && error.norm() <= params_.tolerance_m) {
    ++still_updates_;
    return {};
  }
  still_updates_ = 0;
  // Outside the cell (a moving obstacle came closer, or a neighbour's news
  // did) the way back in may be short but is urgent: full speed.
  Eigen::Vector2d velocity = inside ? Eigen::Vector2d(params_.gain * error) : error;
  if (!(velocity.norm() <= params_.max_speed_mps) || !inside) {
    velocity *= velocity.norm() > 0.0 ? params_.max_speed_mps / velocity.norm() : 0.0;
  }
  agents::UnicycleCommand command = LimitActuators(DxiToDxu(velocity));
  // Slowing down never raises a wheel's speed, so the limits still hold.
  command.v_mps = SafeSpeed(command.v_mps, cell.constraints(), position, heading, horizon_s);
  if (inside) {
    // Safe where it is: then also never move away from the coverage centroid
    // (with the unicycle's curved path a step towards the goal could).
    command.v_mps = DescentSpeed(command.v_mps, cell.coverage_centroid_m(), position, heading, horizon_s);
  }
  return command;
}

double VoronoiCoverageRobot::DescentSpeed(double v_mps, const Eigen::Vector2d& centroid_m,
                                          const Eigen::Vector2d& position_m, double heading_rad, double step_s) {
  // A step s = step_s v along h changes ||p - c||^2 by s^2 - 2 s h.(c - p):
  // no increase for s between 0 and 2 h.(c - p); allow half of that, so the
  // distance strictly shrinks whenever the robot moves.
  const double toward = Eigen::Vector2d(std::cos(heading_rad), std::sin(heading_rad)).dot(centroid_m - position_m);
  const double limit_mps = toward / step_s;
  return limit_mps >= 0.0 ? std::clamp(v_mps, 0.0, limit_mps) : std::clamp(v_mps, limit_mps, 0.0);
}

}  // namespace dream::voronoi_coverage
