#include "dream/line_deployment/line_deployment_robot.h"
#include "dream/agents/fields/field_check.h"

#include <cmath>
#include <stdexcept>

#include "dream/agents/framework/position_message.h"
#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/params_check.h"

namespace dream::line_deployment {

bool LineDeploymentParams::IsValid(std::string* error) const {
  if (!agents::CheckFields(*this, error)) return false;
  if (!(resume_m >= tolerance_m) || !std::isfinite(resume_m)) {
    return agents::FailParams(error, "resume_m must be >= tolerance_m (" + agents::NumberText(tolerance_m) + "), got " +
                                         agents::NumberText(resume_m));
  }
  if (!(arena_margin_m >= 0.0) || !arena_min_m.allFinite() || !arena_max_m.allFinite() ||
      !((arena_max_m - arena_min_m).array() > 2.0 * arena_margin_m).all()) {
    return agents::FailParams(error, "arena_margin_m must be >= 0 and leave room inside the arena, got " +
                                         agents::NumberText(arena_margin_m));
  }
  return true;
}

LineDeploymentRobot::LineDeploymentRobot(int id, const agents::RobotParams& robot_params,
                                         const agents::HrvoRobotParams& hrvo_params, const LineDeploymentParams& params)
    : agents::HrvoRobot(id, robot_params, hrvo_params), params_(agents::CheckedParams(params)) {}

void LineDeploymentRobot::OnMovement(const agents::MovementReading& reading) {
  if (moving_) {
    agents::HrvoRobot::OnMovement(reading);
    return;
  }
  near_.step = reading.step;
  near_.neighbours.clear();
  for (const agents::NeighbourDetection& n : reading.neighbours) {
    if (n.distance_m < params_.hold_avoid_range_m) near_.neighbours.push_back(n);
  }
  agents::HrvoRobot::OnMovement(near_);
}

std::optional<std::vector<uint8_t>> LineDeploymentRobot::OnRadio(const std::vector<agents::RadioMessage>& heard) {
  for (const agents::RadioMessage& message : heard) {
    // A payload claiming another robot's id is as bad as a truncated one.
    const std::optional<agents::PositionMessage> neighbour =
        agents::PositionMessage::Decode(message.payload, message.sender_id);
    if (!neighbour) {
      CountBadRadioMessage(message);
      continue;
    }
    neighbours_[neighbour->id] = neighbour->position_m;
  }
  if (!has_odometry()) return std::nullopt;  // do not advertise a position we do not know
  return agents::PositionMessage{id(), pose().head<2>()}.Encode();
}

std::optional<Eigen::Vector2d> LineDeploymentRobot::Target() const {
  std::vector<NeighbourPosition> neighbours;
  neighbours.reserve(neighbours_.size());
  for (const auto& [neighbour_id, position] : neighbours_) neighbours.push_back({neighbour_id, position});
  const std::optional<Eigen::Vector2d> target = LineConsensusTarget(id(), neighbours, params_.spacing_m);
  if (!target) return std::nullopt;
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(params_.arena_margin_m);
  return Eigen::Vector2d(target->cwiseMax(params_.arena_min_m + margin).cwiseMin(params_.arena_max_m - margin));
}

agents::UnicycleCommand LineDeploymentRobot::Update(int64_t step) {
  (void)step;
  if (!has_odometry()) return {};
  Eigen::Vector2d preferred = Eigen::Vector2d::Zero();
  const std::optional<Eigen::Vector2d> target = Target();
  if (target) {
    const Eigen::Vector2d error = *target - pose().head<2>();
    const double distance = error.norm();
    if (moving_ && distance < params_.tolerance_m) moving_ = false;
    if (!moving_ && distance > params_.resume_m) moving_ = true;
    if (moving_) {
      settled_updates_ = 0;
      preferred = params_.gain * error;
      if (preferred.norm() > params_.max_speed_mps) preferred *= params_.max_speed_mps / preferred.norm();
    } else {
      ++settled_updates_;
    }
  }
  return DriveWithVelocity(preferred);
}

}  // namespace dream::line_deployment
