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
class GoToGoalBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "go_to_goal";
  /// The kind's section: each robot's goal and the robots' keys, each named once.
  struct Section {
    std::vector<Eigen::Vector2d> goals;
    GoToGoalParams robot;
    template <typename Fields>
    void ListFields(Fields& fields) {
      fields.RobotPoints("goals", goals, "goal");
      robot.ListFields(fields);
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
};

}  // namespace dream::go_to_goal
