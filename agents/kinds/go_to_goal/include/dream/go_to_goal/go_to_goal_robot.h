#pragma once

#include <Eigen/Core>
#include <string>

#include "dream/agents/fields/field_rule.h"
#include "dream/agents/framework/robot.h"
#include "dream/agents/geometry/single_integrator_to_unicycle.h"

namespace dream::go_to_goal {

/// Parameters of GoToGoalRobot.
struct GoToGoalParams {
  Eigen::Vector2d goal_m = Eigen::Vector2d::Zero();  ///< goal position, world frame
  double gain = 0.8;                                 ///< proportional gain, 1/s; must be positive
  double max_speed_mps = 0.15;                       ///< cap on the planar velocity; (0, 0.2]
  double tolerance_m = 0.03;                         ///< within this distance the robot stops and reports done; > 0

  /// The config keys (`controller:` of kind go_to_goal), once for reading, checking and the docs.
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("gain", gain, agents::FieldRule::Positive(), "proportional gain, 1/s");
    fields.Number("max_speed_mps", max_speed_mps, agents::FieldRule::RobotSpeed(), "cap on the planar velocity, m/s");
    fields.Number("tolerance_m", tolerance_m, agents::FieldRule::Positive(),
                  "within this distance the robot stops and reports done, m");
  }
  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

/// The simplest scripted robot: drive to a fixed goal, knowing only its
/// odometry. Proportional single-integrator law dxi = k (goal - p), capped at
/// max_speed (the Robotarium's si position controller), mapped to the unicycle
/// as the Robotarium's si_to_uni does, limited to what the wheels can do.
/// Stops and reports done within tolerance; holds still before its first
/// odometry reading.
class GoToGoalRobot final : public agents::Robot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  GoToGoalRobot(int id, const agents::RobotParams& robot_params, const GoToGoalParams& params);
  agents::UnicycleCommand Update(int64_t step) override;
  bool done() const override { return done_; }

 private:
  GoToGoalParams params_;
  agents::SingleIntegratorToUnicycle si_to_uni_;
  bool done_ = false;
};

}  // namespace dream::go_to_goal
