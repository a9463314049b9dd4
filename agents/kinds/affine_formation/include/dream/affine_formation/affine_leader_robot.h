#pragma once

#include <Eigen/Core>
#include <string>

#include "dream/affine_formation/affine_maneuver.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/geometry/reversible_si_to_uni.h"
#include "dream/agents/framework/robot.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::affine_formation {

/// Parameters of AffineLeaderRobot.
struct AffineLeaderParams {
  Eigen::Vector2d nominal_m = Eigen::Vector2d::Zero();  ///< this leader's r_i
  AffineManeuverParams maneuver;                        ///< the plan every leader knows
  double gain = 1.5;                                    ///< position feedback, 1/s; > 0
  double max_speed_mps = 0.2;                           ///< cap on the planar velocity; (0, 0.2]
  /// Length of one step, s (turns per-step rates into m/s); > 0.
  double time_step_s = robotarium::RobotariumConstants::kTimeStepSeconds;
  /// Drive with ReversibleSiToUni (default) or the thesis's dxi_to_dxu.
  bool reversible_drive = true;

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;

  /// The config keys of `leader:` (kind affine_formation).
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("gain", gain, agents::FieldRule::Positive(),
                  "leaders' feedback gain on top of the target velocity, 1/s");
    fields.Number("max_speed_mps", max_speed_mps, agents::FieldRule::RobotSpeed(), "leaders' speed cap, m/s");
  }
};

/// A leader of the affine formation: it knows the maneuver and tracks its
/// target p_i*(t) = A(t) r_i + b(t) with the target's velocity fed forward,
///   dxi = dp_i*/dt + gain (p_i* - p_i),  capped at max speed,
/// driven through ReversibleSiToUni (or the thesis's dxi_to_dxu) and the
/// actuator limits. It does not look at the followers (the thesis: leaders
/// ignore them; followers avoid) nor at the obstacles (the plan is timed).
/// Its radio only publishes: position and the velocity it commands at that
/// step (FormationStateMessage), for the followers' law.
class AffineLeaderRobot final : public agents::Robot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  AffineLeaderRobot(int id, const agents::RobotParams& robot_params, const AffineLeaderParams& params);

  void OnOdometry(const agents::OdometryReading& reading) override;
  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<agents::RadioMessage>& heard) override;
  agents::UnicycleCommand Update(int64_t step) override;

  /// The planar velocity commanded at the last update.
  const Eigen::Vector2d& velocity_mps() const { return velocity_mps_; }

 private:
  /// Target velocity plus feedback, capped: what Update commands at `step`.
  Eigen::Vector2d Velocity(int64_t step) const;

  AffineLeaderParams params_;
  AffineManeuver maneuver_;
  agents::ReversibleSiToUni drive_;
  Eigen::Vector2d velocity_mps_ = Eigen::Vector2d::Zero();
  int64_t odometry_step_ = 0;
};

}  // namespace dream::affine_formation
