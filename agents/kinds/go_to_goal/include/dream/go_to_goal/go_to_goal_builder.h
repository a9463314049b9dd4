#pragma once

#include <vector>

#include "dream/kind_api/experiment_builder.h"
#include "dream/agents/fields/field_names.h"
#include "dream/go_to_goal/go_to_goal_robot.h"
#include "dream/config/config_node.h"

namespace dream::go_to_goal {

/// `kind: go_to_goal`: every robot drives to its own goal.
///     goals: [[x, y], ...]   one per robot, metres
///     gain: 0.8   max_speed_mps: 0.15   tolerance_m: 0.03
///     goal_tolerance_m: 0.05   the goal is judged by this (0: tolerance_m)
class GoToGoalBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "go_to_goal";
  /// The kind's section: each robot's goal and the robots' keys, each named once.
  struct Section {
    std::vector<Eigen::Vector2d> goals;
    GoToGoalParams robot;
    /// The goal: every robot this close to its goal at once, measured on the
    /// log's poses (the true ones; the tracker's for a lab run). Apart from
    /// `tolerance_m`, where robots stop, so a lab run's millimetres do not
    /// decide it; 0: `tolerance_m`.
    double goal_tolerance_m = 0.0;
    template <typename Fields>
    void ListFields(Fields& fields) {
      fields.RobotPoints("goals", goals, "goal");
      robot.ListFields(fields);
      fields.Number("goal_tolerance_m", goal_tolerance_m, agents::FieldRule::NonNegative(),
                    "the goal is met when every robot is within this of its goal at once (true poses; the "
                    "tracker's in a lab run), m; 0: tolerance_m");
    }
  };
  /// Keys of this kind besides the common ones.
  static std::vector<std::string> Keys() { return agents::KeysOf<Section>(); }

  GoToGoalBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override;

 private:
  std::vector<GoToGoalParams> params_;
  double goal_tolerance_m_ = 0.0;  ///< 0: each robot's tolerance_m
};

}  // namespace dream::go_to_goal
