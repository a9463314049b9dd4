#include "dream/hrvo_circle/hrvo_circle_builder.h"

#include <cmath>

#include "dream/hrvo_circle/formation_sequence_metrics.h"
#include "dream/kind_api/field_reader.h"
#include "dream/agents/framework/number_text.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::hrvo_circle {

kind_api::AgentPartsConfig HrvoCircleBuilder::DefaultParts(int num_robots) {
  kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::ThesisHrvoParts(num_robots);
  parts.radio = kind_api::RadioConfig::Every(kind_api::RadioConfig::Kind::kRange, num_robots, 30);
  parts.radio.range_m = 1.0;
  return parts;
}

HrvoCircleBuilder::HrvoCircleBuilder(const config::ConfigNode& section, int num_robots) : num_robots_(num_robots) {
  Section fields;
  kind_api::ReadFields(section, num_robots, &fields);
  const double radius_m = fields.radius_m;
  const Eigen::Vector2d center = fields.center;
  const int formations = fields.formations;
  params_ = fields.robot;
  params_.num_robots = num_robots;
  hrvo_ = fields.hrvo;
  std::string hrvo_error;
  if (!hrvo_.IsValid(&hrvo_error)) section.Required("hrvo").FailAtField(hrvo_error);

  // Appendix B's p_circ: robot i at angle 2 pi i / N, its opposite at + pi.
  for (int k = 0; k < formations; ++k) {
    std::vector<Eigen::Vector2d> points;
    for (int i = 0; i < num_robots; ++i) {
      const double angle = 2.0 * M_PI * i / num_robots + (k % 2 == 1 ? M_PI : 0.0);
      points.push_back(center + radius_m * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
    }
    formations_.push_back(points);
  }
  // Every point must lie in the arena with a robot's margin, or HRVO's
  // boundary check would keep the robot from ever reaching it.
  constexpr double kMarginM = 0.1;
  using Arena = robotarium::RobotariumConstants;
  for (const auto& formation : formations_) {
    for (const Eigen::Vector2d& p : formation) {
      if (p.x() < Arena::kArenaXMinMeters + kMarginM || p.x() > Arena::kArenaXMaxMeters - kMarginM ||
          p.y() < Arena::kArenaYMinMeters + kMarginM || p.y() > Arena::kArenaYMaxMeters - kMarginM) {
        section.Fail("the circle (center [" + std::to_string(center.x()) + ", " + std::to_string(center.y()) +
                     "], radius_m " + std::to_string(radius_m) + ") leaves the arena: every point must be " +
                     agents::NumberText(kMarginM) + " m inside x in [" + agents::NumberText(Arena::kArenaXMinMeters) +
                     ", " + agents::NumberText(Arena::kArenaXMaxMeters) + "], y in [" +
                     agents::NumberText(Arena::kArenaYMinMeters) + ", " + agents::NumberText(Arena::kArenaYMaxMeters) +
                     "]");
      }
    }
  }
  CircleFormationParams check = params_;
  check.goals_m = {Eigen::Vector2d::Zero()};
  std::string error;
  if (!check.IsValid(&error)) section.FailAtField(error);
}

std::unique_ptr<agents::Robot> HrvoCircleBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  CircleFormationParams robot = params_;
  for (const auto& formation : formations_) robot.goals_m.push_back(formation.at(static_cast<size_t>(robot_id)));
  return std::make_unique<CircleFormationRobot>(robot_id, params, hrvo_, robot);
}

std::unique_ptr<agents::ExperimentMetrics> HrvoCircleBuilder::MakeMetrics() const {
  return std::make_unique<FormationSequenceMetrics>(formations_, params_.tolerance_m);
}

std::vector<std::vector<Eigen::Vector2d>> HrvoCircleBuilder::GoalsToDraw() const {
  std::vector<std::vector<Eigen::Vector2d>> goals(static_cast<size_t>(num_robots_));
  for (const std::vector<Eigen::Vector2d>& formation : formations_) {
    for (size_t i = 0; i < formation.size() && i < goals.size(); ++i) goals[i].push_back(formation[i]);
  }
  return goals;
}

}  // namespace dream::hrvo_circle
