#pragma once

#include <memory>
#include <vector>

#include "dream/agents/experiments/affine_follower_robot.h"
#include "dream/agents/experiments/affine_formation_metrics.h"
#include "dream/agents/experiments/affine_leader_robot.h"
#include "dream/agent_host/agent_parts_config.h"
#include "dream/agent_host/experiment_builder.h"
#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/agents/experiments/stress_formation.h"
#include "dream/config/config_node.h"

namespace dream::agent_host {

/// `kind: affine_formation`: the thesis's affine formation maneuver (section
/// 3.4; Zhao 2018 section VII). The role radio carries the formation: its
/// `graph` is the stress weight matrix w (followers hear exactly their
/// non-zero entries) and its `leaders` lead.
///     nominal_positions: [[x, y], ...]   one per robot; w must be an equilibrium stress of them
///     maneuver: [{step: 0, scale_x: 1, scale_y: 1, rotation_rad: 0, translation: [0, 0]}, ...]
///     leader:   {gain: 1.5, max_speed_mps: 0.2}
///     follower: {law: zhao | thesis, gain: 1.0, max_speed_mps: 0.2, hrvo_engage_distance_m: 0.27,
///                hrvo_horizon_s: 1.5, max_message_age_steps: 30}
///     hrvo:     {variant: exact | thesis, safety_radius_m: 0.2, ...}   (followers only)
///     drive:    reversible | thesis   (ReversibleSiToUni or dxi_to_dxu, every robot)
///     time_step_s: 0.033   equilibrium_tolerance_m: 0.005   min_target_spacing_m: 0.25
///     metrics:  {tolerance_m: 0.05, converged_from_step: 0, obstacle_pairs: [[0, 1]], series_every_steps: 10}
class AffineFormationBuilder final : public ExperimentBuilder {
 public:
  static constexpr const char* kKind = "affine_formation";
  /// The followers need every leader's word: the role radio's graph must connect.
  static constexpr bool kGraphMustConnect = true;
  static std::vector<const char*> Keys() {
    return {"nominal_positions", "maneuver", "leader", "follower", "hrvo", "drive", "time_step_s",
            "equilibrium_tolerance_m", "min_target_spacing_m", "metrics"};
  }
  /// Every part every step: robot, odometry and movement sensor (1 m) period
  /// 1, role radio period 1 (its graph and leaders come from the config).
  static AgentPartsConfig DefaultParts(int num_robots);

  AffineFormationBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override;

  const agents::StressFormation& formation() const { return *formation_; }
  const agents::AffineManeuverParams& maneuver() const { return maneuver_; }

 private:
  std::unique_ptr<agents::StressFormation> formation_;
  agents::AffineManeuverParams maneuver_;
  agents::AffineLeaderParams leader_;
  agents::AffineFollowerParams follower_;
  agents::HrvoRobotParams hrvo_;
  agents::AffineFormationMetricsParams metrics_;
};

}  // namespace dream::agent_host
