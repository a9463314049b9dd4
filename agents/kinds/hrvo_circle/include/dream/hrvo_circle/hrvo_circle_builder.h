#pragma once

#include <Eigen/Core>
#include <vector>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/agents/fields/field_names.h"
#include "dream/hrvo_circle/circle_formation_robot.h"
#include "dream/kind_api/experiment_builder.h"
#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/config/config_node.h"

namespace dream::hrvo_circle {

/// `kind: hrvo_circle`: the thesis's HRVO experiment (section 3.1, Appendix
/// B). Robot i's point is on a circle at angle 2 pi i / N; formation k
/// (0-based) puts it there for even k and at the diametrically opposite point
/// for odd k. Robots move to the next formation only when the radio has told
/// them that everybody reached the current one (CircleFormationRobot).
///     radius_m: 0.85   center: [0, 0]   formations: 3
///     tolerance_m: 0.05   max_speed_mps: 0.2
///     hrvo: {variant: exact | thesis, safety_radius_m: 0.24, ...}
class HrvoCircleBuilder final : public kind_api::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "hrvo_circle";
  /// The kind's section: the circle's, the robots' and HRVO's keys, each named once.
  struct Section {
    double radius_m = 0.85;
    Eigen::Vector2d center = Eigen::Vector2d::Zero();
    int formations = 3;
    CircleFormationParams robot;
    agents::HrvoRobotParams hrvo;
    template <typename Fields>
    void ListFields(Fields& fields) {
      fields.Number("radius_m", radius_m, agents::FieldRule::Positive(),
                    "circle radius (Appendix B), m; every point must lie 0.1 m inside the arena");
      fields.Point("center", center, "circle centre `[x, y]`, m");
      fields.Whole("formations", formations, agents::FieldRule::Within(1, 100),
                   "how many formations in turn (circle, opposite, circle, ...)");
      robot.ListFields(fields);
      fields.Section("hrvo", hrvo, "collision avoidance");
    }
  };
  static std::vector<std::string> Keys() { return agents::KeysOf<Section>(); }
  /// Appendix B's parts: robot period 4+(i%2), start delay 20+i; odometry
  /// every 2+(i%2), movement sensor every 3+(i%2) (range 1 m); range radio
  /// (1 m) every 30 steps.
  static kind_api::AgentPartsConfig DefaultParts(int num_robots);

  HrvoCircleBuilder(const config::ConfigNode& section, int num_robots);
  std::unique_ptr<agents::Robot> MakeRobot(int robot_id, const agents::RobotParams& params) const override;
  std::unique_ptr<agents::ExperimentMetrics> MakeMetrics() const override;
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const override;

  /// formations()[k][i]: robot i's point in formation k.
  const std::vector<std::vector<Eigen::Vector2d>>& formations() const { return formations_; }

 private:
  int num_robots_;
  CircleFormationParams params_;  // goals_m filled per robot
  agents::HrvoRobotParams hrvo_;
  std::vector<std::vector<Eigen::Vector2d>> formations_;
};

}  // namespace dream::hrvo_circle
