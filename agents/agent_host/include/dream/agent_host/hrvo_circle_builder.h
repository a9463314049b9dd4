#pragma once

#include <Eigen/Core>
#include <vector>

#include "dream/agent_host/agent_parts_config.h"
#include "dream/agents/experiments/circle_formation_robot.h"
#include "dream/agent_host/experiment_builder.h"
#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/config/config_node.h"

namespace dream::agent_host {

/// `kind: hrvo_circle`: the thesis's HRVO experiment (section 3.1, Appendix
/// B). Robot i's point is on a circle at angle 2 pi i / N; formation k
/// (0-based) puts it there for even k and at the diametrically opposite point
/// for odd k. Robots move to the next formation only when the radio has told
/// them that everybody reached the current one (CircleFormationRobot).
///     radius_m: 0.85   center: [0, 0]   formations: 3
///     tolerance_m: 0.05   max_speed_mps: 0.2
///     hrvo: {variant: exact | thesis, safety_radius_m: 0.24, ...}
class HrvoCircleBuilder final : public ExperimentBuilder {
 public:
  static constexpr const char* kKind = "hrvo_circle";
  static std::vector<const char*> Keys() {
    return {"radius_m", "center", "formations", "tolerance_m", "max_speed_mps", "gain", "stop_m", "hrvo"};
  }
  /// Appendix B's parts: robot period 4+(i%2), start delay 20+i; odometry
  /// every 2+(i%2), movement sensor every 3+(i%2) (range 1 m); range radio
  /// (1 m) every 30 steps.
  static AgentPartsConfig DefaultParts(int num_robots);

  HrvoCircleBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override;

  /// formations()[k][i]: robot i's point in formation k.
  const std::vector<std::vector<Eigen::Vector2d>>& formations() const { return formations_; }

 private:
  int num_robots_;
  agents::CircleFormationParams params_;  // goals_m filled per robot
  agents::HrvoRobotParams hrvo_;
  std::vector<std::vector<Eigen::Vector2d>> formations_;
};

}  // namespace dream::agent_host
