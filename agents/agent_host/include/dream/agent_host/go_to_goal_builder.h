#pragma once

#include <vector>

#include "dream/agent_host/experiment_builder.h"
#include "dream/agents/experiments/go_to_goal_robot.h"
#include "dream/config/config_node.h"

namespace dream::agent_host {

/// `kind: go_to_goal`: every robot drives to its own goal.
///     goals: [[x, y], ...]   one per robot, metres
///     gain: 0.8   max_speed_mps: 0.15   tolerance_m: 0.03
class GoToGoalBuilder final : public ExperimentBuilder {
 public:
  static constexpr const char* kKind = "go_to_goal";
  /// Keys of this kind besides the common ones.
  static std::vector<const char*> Keys() { return {"goals", "gain", "max_speed_mps", "tolerance_m"}; }

  GoToGoalBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override;

 private:
  std::vector<agents::GoToGoalParams> params_;
};

}  // namespace dream::agent_host
