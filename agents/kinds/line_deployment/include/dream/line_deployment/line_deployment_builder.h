#pragma once

#include <Eigen/Core>
#include <vector>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/agents/fields/field_names.h"
#include "dream/kind_api/experiment_builder.h"
#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/line_deployment/line_deployment_robot.h"
#include "dream/config/config_node.h"

namespace dream::line_deployment {

/// `kind: line_deployment`: the thesis's consensus line (section 3.2, eq.
/// 3.7) over a graph radio; robots end on one horizontal line ordered by id,
/// spacing_m apart.
///     spacing_m: 0.4   gain: 2.0   max_speed_mps: 0.2   tolerance_m: 0.0015   resume_m: 0.003
///     hold_avoid_range_m: 0.3   settle_updates: 20   arena_margin_m: 0.15   converged_m: 0.02
///     hrvo: {...}
/// A graph radio's adjacency must be symmetric and connected (the factory
/// checks it: graph_must_connect).
class LineDeploymentBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "line_deployment";
  /// Consensus (eq. 3.7) needs a symmetric, connected graph.
  static constexpr bool kGraphMustConnect = true;
  /// The kind's section: the robots', the metrics' and HRVO's keys, each named once.
  struct Section {
    LineDeploymentParams robot;
    double converged_m = 0.02;
    agents::HrvoRobotParams hrvo;
    template <typename Fields>
    void ListFields(Fields& fields) {
      robot.ListFields(fields);
      fields.Number("converged_m", converged_m, agents::FieldRule::Positive(),
                    "metrics: converged once both line errors stay below this, m");
      fields.Section("hrvo", hrvo, "collision avoidance");
    }
  };
  static std::vector<std::string> Keys() { return agents::KeysOf<Section>(); }
  /// The thesis's 6x6 adjacency matrix (section 3.2.2).
  static Eigen::MatrixXd ThesisAdjacency();
  /// Appendix B's timings (robot 4+(i%2), start delay 20+i, odometry 2+(i%2),
  /// movement 3+(i%2)); graph radio every 10 steps over ThesisAdjacency() for
  /// 6 robots, a path 0-1-...-(N-1) otherwise.
  static kind_api::AgentPartsConfig DefaultParts(int num_robots);

  LineDeploymentBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;

 private:
  LineDeploymentParams params_;
  agents::HrvoRobotParams hrvo_;
  double converged_m_ = 0.02;
};

}  // namespace dream::line_deployment
