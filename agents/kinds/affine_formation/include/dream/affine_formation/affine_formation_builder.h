#pragma once

#include <memory>
#include <vector>

#include "dream/affine_formation/affine_follower_robot.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/agents/fields/field_names.h"
#include "dream/affine_formation/affine_formation_metrics.h"
#include "dream/affine_formation/affine_leader_robot.h"
#include "dream/kind_api/agent_parts_config.h"
#include "dream/kind_api/experiment_builder.h"
#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/affine_formation/stress_formation.h"
#include "dream/config/config_node.h"

namespace dream::affine_formation {

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
class AffineFormationBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "affine_formation";
  /// The followers need every leader's word: the role radio's graph must connect.
  static constexpr bool kGraphMustConnect = true;
  /// The kind's section: every key named once (the maneuver's and the
  /// obstacle pairs' structure is read by the builder).
  struct Section {
    std::vector<Eigen::Vector2d> nominal_positions;
    AffineLeaderParams leader;
    AffineFollowerParams follower;
    agents::HrvoRobotParams hrvo = FormationHrvo();
    bool reversible_drive = true;
    double time_step_s = robotarium::RobotariumConstants::kTimeStepSeconds;
    double equilibrium_tolerance_m = StressFormationParams{}.equilibrium_tolerance_m;
    double min_target_spacing_m = 0.25;
    AffineFormationMetricsParams metrics;
    static constexpr const char* kManeuverKey = "maneuver";

    template <typename Fields>
    void ListFields(Fields& fields) {
      fields.RobotPoints("nominal_positions", nominal_positions, "nominal position");
      fields.Custom(kManeuverKey,
                    "required: keyframes `{step, scale_x: 1, scale_y: 1, rotation_rad: 0, translation: [0, 0]}` at "
                    "increasing steps: A = diag(scale_x, scale_y) R(rotation_rad), b = translation, smoothstep between "
                    "keyframes, held outside");
      fields.Section("leader", leader, "the leaders' law");
      fields.Section("follower", follower, "the followers' law");
      fields.Section("hrvo", hrvo, "collision avoidance");
      fields.Choice("drive", reversible_drive, {{"reversible", true}, {"thesis", false}},
                    "drive of every robot: `reversible` (may back up instead of turning round, with hysteresis) or "
                    "`thesis` (dxi_to_dxu)");
      fields.Number("time_step_s", time_step_s, agents::FieldRule::Positive(),
                    "one step: leaders' target velocities, followers' ageing of neighbour positions, s");
      fields.Number("equilibrium_tolerance_m", equilibrium_tolerance_m, agents::FieldRule::Positive(),
                    "how far a follower's stress equilibrium may lie from its nominal point (weights rounded to 4 "
                    "decimals move it < 1 mm), m");
      fields.Number("min_target_spacing_m", min_target_spacing_m, agents::FieldRule::NonNegative(),
                    "every step of the plan must keep all targets this far apart and 0.1 m inside the arena (checked "
                    "when the config loads), m");
      fields.Section("metrics", metrics, "the formation's metrics");
    }
    /// HRVO's defaults here: the formation keeps robots >= 0.3 m apart.
    static agents::HrvoRobotParams FormationHrvo() {
      agents::HrvoRobotParams hrvo;
      hrvo.hrvo.safety_radius_m = 0.2;
      return hrvo;
    }
  };
  static std::vector<std::string> Keys() { return agents::KeysOf<Section>(); }
  /// Every part every step: robot, odometry and movement sensor (1 m) period
  /// 1, role radio period 1 (its graph and leaders come from the config).
  static kind_api::AgentPartsConfig DefaultParts(int num_robots);

  AffineFormationBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override;

  const StressFormation& formation() const { return *formation_; }
  const AffineManeuverParams& maneuver() const { return maneuver_; }

 private:
  void ReadFormation(const config::ConfigNode& section, const Section& fields, int num_robots);
  void ReadFollowerLaw(const config::ConfigNode& section);
  void ReadMetrics(const config::ConfigNode& section, const Section& fields);

  std::unique_ptr<StressFormation> formation_;
  AffineManeuverParams maneuver_;
  AffineLeaderParams leader_;
  AffineFollowerParams follower_;
  agents::HrvoRobotParams hrvo_;
  AffineFormationMetricsParams metrics_;
};

}  // namespace dream::affine_formation
