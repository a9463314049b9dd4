#include "dream/affine_formation/affine_follower_robot.h"
#include "dream/agents/fields/field_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dream/affine_formation/formation_state_message.h"
#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/params_check.h"

namespace dream::affine_formation {

bool AffineFollowerParams::IsValid(std::string* error) const {
  if (neighbours.empty())
    return agents::FailParams(error, "neighbours: a follower needs at least one weighted neighbour");
  double gamma = 0.0;
  for (size_t k = 0; k < neighbours.size(); ++k) {
    const auto& [j, w] = neighbours[k];
    if (j < 0) return agents::FailParams(error, "neighbours: id " + std::to_string(j) + " is not a robot id");
    if (!std::isfinite(w) || w == 0.0) {
      return agents::FailParams(error, "neighbours: weight of robot " + std::to_string(j) +
                                           " must be finite and non-zero, got " + std::to_string(w));
    }
    for (size_t m = 0; m < k; ++m) {
      if (neighbours[m].first == j) {
        return agents::FailParams(error, "neighbours: robot " + std::to_string(j) + " is listed twice");
      }
    }
    gamma += w;
  }
  if (law == Law::kZhao && !(gamma > 0.0)) {
    return agents::FailParams(error, "neighbours: the weights sum to " + std::to_string(gamma) +
                                         "; Zhao's law divides by that sum, which must be > 0");
  }
  return agents::CheckFields(*this, error) && agents::CheckPositive(error, "time_step_s", time_step_s);
}

AffineFollowerRobot::AffineFollowerRobot(int id, const agents::RobotParams& robot_params,
                                         const agents::HrvoRobotParams& hrvo, const AffineFollowerParams& params)
    : agents::HrvoRobot(id, robot_params, hrvo),
      params_(agents::CheckedParams(params)),
      safety_radius_m_(hrvo.hrvo.safety_radius_m),
      drive_(robot_params.vel_gain, robot_params.ang_gain) {
  for (const auto& [j, w] : params_.neighbours) {
    if (j == id) throw std::invalid_argument("neighbours: robot " + std::to_string(id) + " lists itself");
    Neighbour neighbour;
    neighbour.id = j;
    neighbour.weight = w;
    neighbours_.push_back(neighbour);
    gamma_ += w;
  }
}

void AffineFollowerRobot::OnOdometry(const agents::OdometryReading& reading) {
  agents::HrvoRobot::OnOdometry(reading);
  odometry_step_ = reading.step;
}

void AffineFollowerRobot::OnMovement(const agents::MovementReading& reading) { sensed_ = reading; }

std::optional<std::vector<uint8_t>> AffineFollowerRobot::OnRadio(const std::vector<agents::RadioMessage>& heard) {
  for (const agents::RadioMessage& message : heard) {
    auto it = std::find_if(neighbours_.begin(), neighbours_.end(),
                           [&](const Neighbour& n) { return n.id == message.sender_id; });
    if (it == neighbours_.end()) continue;  // not a graph neighbour: not part of the law
    // The mailbox repeats a sender's latest message until a newer one comes:
    // judge each message once.
    if (message.sent_step <= it->last_heard_step) continue;
    it->last_heard_step = message.sent_step;
    const std::optional<FormationStateMessage> state =
        FormationStateMessage::Decode(message.payload, message.sender_id);
    if (!state) {
      CountBadRadioMessage(message);
      continue;
    }
    it->known = true;
    it->sent_step = message.sent_step;
    it->position_m = state->position_m;
    it->velocity_mps = state->velocity_mps;
  }
  if (!has_odometry()) return std::nullopt;
  // Report the velocity the law asks for now, from what was just heard, not
  // the one commanded at the last update: neighbours feed it forward, and a
  // step less of delay in that loop is what keeps Zhao's law stable at
  // useful gains (docs/experiments.md).
  const Eigen::Vector2d velocity = LawVelocity(odometry_step_).value_or(Eigen::Vector2d::Zero());
  return FormationStateMessage{id(), pose().head<2>(), velocity}.Encode();
}

bool AffineFollowerRobot::knows_all_neighbours() const {
  return std::all_of(neighbours_.begin(), neighbours_.end(), [](const Neighbour& n) { return n.known; });
}

std::optional<Eigen::Vector2d> AffineFollowerRobot::LawVelocity(int64_t step) const {
  const Eigen::Vector2d p = pose().head<2>();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const Neighbour& n : neighbours_) {
    if (!n.known || step - n.sent_step > params_.max_message_age_steps) return std::nullopt;
    if (params_.law == AffineFollowerParams::Law::kThesis) {
      sum -= params_.gain * n.weight * (p - n.position_m);
    } else {
      // Where the neighbour is now, if it kept the velocity it reported.
      const Eigen::Vector2d p_j = n.position_m + n.velocity_mps * (double(step - n.sent_step) * params_.time_step_s);
      sum += n.weight * (n.velocity_mps - params_.gain * (p - p_j));
    }
  }
  Eigen::Vector2d velocity = params_.law == AffineFollowerParams::Law::kThesis ? sum : Eigen::Vector2d(sum / gamma_);
  if (velocity.norm() > params_.max_speed_mps) velocity *= params_.max_speed_mps / velocity.norm();
  return velocity;
}

agents::UnicycleCommand AffineFollowerRobot::Update(int64_t step) {
  if (!has_odometry()) return {};
  preferred_mps_ = LawVelocity(step).value_or(Eigen::Vector2d::Zero());
  // HRVO sees the robots that are close, or that the preferred velocity
  // closes on fast enough to reach the safety radius within the horizon.
  agents::MovementReading engaged;
  engaged.step = sensed_.step;
  for (const agents::NeighbourDetection& detection : sensed_.neighbours) {
    bool engage = detection.distance_m < params_.hrvo_engage_distance_m;
    if (!engage) {
      const Eigen::Vector2d towards = detection.RelativePosition() / detection.distance_m;
      const double closing_mps = (preferred_mps_ - detection.velocity_mps).dot(towards);
      engage = closing_mps > 0.0 && detection.distance_m - safety_radius_m_ < closing_mps * params_.hrvo_horizon_s;
    }
    if (engage) engaged.neighbours.push_back(detection);
  }
  hrvo_engaged_ = static_cast<int>(engaged.neighbours.size());
  agents::HrvoRobot::OnMovement(engaged);
  if (!params_.reversible_drive) return DriveWithVelocity(preferred_mps_);
  return LimitActuators(drive_.Map(AvoidCollisions(preferred_mps_), pose().z()));
}

}  // namespace dream::affine_formation
