#include "dream/affine_formation/affine_formation_builder.h"
#include "dream/kind_api/field_reader.h"

#include <algorithm>
#include <cmath>

#include "dream/kind_api/hrvo_config.h"
#include "dream/affine_formation/affine_maneuver.h"
#include "dream/agents/framework/number_text.h"

namespace dream::affine_formation {
namespace {

using config::ConfigNode;

Eigen::Vector2d ReadPoint(const ConfigNode& node) {
  const std::vector<double> xy = node.AsDoubles();
  if (xy.size() != 2) node.Fail("expected [x, y] in metres, got " + std::to_string(xy.size()) + " numbers");
  return {xy[0], xy[1]};
}

AffineManeuverParams ReadManeuver(const ConfigNode& node) {
  if (!node.IsSequence() || node.size() == 0) {
    node.Fail("expected a list of keyframes {step, scale_x, scale_y, rotation_rad, translation}");
  }
  if (node.size() > AffineManeuverParams::kMaxKeyframes) {
    node.Fail("at most " + std::to_string(AffineManeuverParams::kMaxKeyframes) + " keyframes, got " +
              std::to_string(node.size()));
  }
  AffineManeuverParams maneuver;
  for (size_t k = 0; k < node.size(); ++k) {
    const ConfigNode item = node[k];
    item.RejectUnknownKeys({"step", "scale_x", "scale_y", "rotation_rad", "translation"});
    AffineKeyframe frame;
    frame.step = item.Required("step").AsInt();
    frame.scale_x = item.GetDouble("scale_x", frame.scale_x);
    frame.scale_y = item.GetDouble("scale_y", frame.scale_y);
    frame.rotation_rad = item.GetDouble("rotation_rad", frame.rotation_rad);
    if (item.Has("translation")) frame.translation_m = ReadPoint(item.Required("translation"));
    maneuver.keyframes.push_back(frame);
    std::string error;
    if (!maneuver.IsValid(&error)) item.Fail(error);
  }
  return maneuver;
}

// The steps CheckPlan looks at: every step of a segment up to this long; a
// longer one at this many evenly spaced steps. Between two keyframes the
// shapes passed through do not depend on the segment's length (only how fast
// they pass), so this is as fine as checking a 1024-step segment at every
// step, and a keyframe at step 10^12 costs no more than one at 1024.
constexpr int64_t kChecksPerSegment = 1024;

std::vector<int64_t> StepsToCheck(const AffineManeuver& maneuver) {
  std::vector<int64_t> steps{0};
  int64_t from = 0;
  for (const AffineKeyframe& frame : maneuver.keyframes()) {
    const int64_t span = frame.step - from;
    const int64_t count = std::min(span, kChecksPerSegment);
    for (int64_t k = 1; k <= count; ++k) {
      // k * span / count without overflow: span < 2^63, count <= 1024.
      const auto offset = static_cast<int64_t>(static_cast<long double>(span) * k / count);
      steps.push_back(from + offset);
    }
    from = frame.step;
  }
  return steps;
}

// The plan must keep every target inside the arena and apart, or the robots
// cannot follow it: checked at every step (StepsToCheck for long segments), so
// a bad keyframe fails before the run.
void CheckPlan(const ConfigNode& node, const AffineManeuverParams& params, const std::vector<Eigen::Vector2d>& nominal,
               const agents::HrvoParams& arena, double min_spacing_m) {
  const AffineManeuver maneuver(params);
  constexpr double kWallMarginM = 0.1;
  for (const int64_t step : StepsToCheck(maneuver)) {
    const agents::AffineTransform map = maneuver.At(double(step));
    std::vector<Eigen::Vector2d> targets;
    for (const Eigen::Vector2d& r : nominal) targets.push_back(map.Apply(r));
    for (size_t i = 0; i < targets.size(); ++i) {
      const Eigen::Vector2d& p = targets[i];
      if (p.x() < arena.x_min_m + kWallMarginM || p.x() > arena.x_max_m - kWallMarginM ||
          p.y() < arena.y_min_m + kWallMarginM || p.y() > arena.y_max_m - kWallMarginM) {
        node.Fail("at step " + std::to_string(step) + " robot " + std::to_string(i) + "'s target (" +
                  agents::NumberText(p.x()) + ", " + agents::NumberText(p.y()) + ") is not 0.1 m inside the arena");
      }
      for (size_t j = 0; j < i; ++j) {
        const double d = (p - targets[j]).norm();
        if (d < min_spacing_m) {
          node.Fail("at step " + std::to_string(step) + " the targets of robots " + std::to_string(j) + " and " +
                    std::to_string(i) + " are " + agents::NumberText(d) + " m apart, less than min_target_spacing_m " +
                    agents::NumberText(min_spacing_m));
        }
      }
    }
  }
}

}  // namespace

kind_api::AgentPartsConfig AffineFormationBuilder::DefaultParts(int num_robots) {
  kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::Defaults(num_robots);
  parts.sensors = {kind_api::SensorConfig::Every(kind_api::SensorConfig::Kind::kOdometry, num_robots, 1),
                   kind_api::SensorConfig::Every(kind_api::SensorConfig::Kind::kMovement, num_robots, 1)};
  parts.radio = kind_api::RadioConfig::Every(kind_api::RadioConfig::Kind::kRole, num_robots, 1);
  return parts;
}

AffineFormationBuilder::AffineFormationBuilder(const ConfigNode& section, int num_robots) {
  Section fields;
  kind_api::ReadFields(section, num_robots, &fields);
  ReadFormation(section, fields, num_robots);
  hrvo_ = fields.hrvo;
  std::string error;
  if (!hrvo_.IsValid(&error)) section.Required("hrvo").FailAtField(error);

  maneuver_ = ReadManeuver(section.Required(Section::kManeuverKey));
  CheckPlan(section.Required(Section::kManeuverKey), maneuver_, formation_->nominal_m(), hrvo_.hrvo,
            fields.min_target_spacing_m);

  leader_ = fields.leader;
  follower_ = fields.follower;
  leader_.reversible_drive = follower_.reversible_drive = fields.reversible_drive;
  leader_.maneuver = maneuver_;
  leader_.time_step_s = follower_.time_step_s = fields.time_step_s;
  const ConfigNode leader = section.Optional("leader");
  if (!leader_.IsValid(&error)) (leader.IsDefined() ? leader : section).FailAtField(error);
  ReadFollowerLaw(section);
  ReadMetrics(section, fields);
}

void AffineFormationBuilder::ReadFormation(const ConfigNode& section, const Section& fields, int num_robots) {
  // The stress weights and the leaders are the role radio's graph and leaders:
  // one matrix says both who hears whom and how much each neighbour counts.
  const ConfigNode radio = section.Required("radio");
  const kind_api::AgentPartsConfig parts =
      kind_api::AgentPartsConfig::Read(section, num_robots, DefaultParts(num_robots), kGraphMustConnect);
  if (parts.radio.kind != kind_api::RadioConfig::Kind::kRole) {
    radio.Required("kind").Fail(
        "an affine formation needs `kind: role` (leaders publish, followers hear their "
        "neighbours in `graph`, the stress weights)");
  }
  StressFormationParams formation;
  formation.weights = parts.radio.graph;
  formation.leaders = parts.radio.leaders;
  formation.nominal_m = fields.nominal_positions;
  formation.equilibrium_tolerance_m = fields.equilibrium_tolerance_m;
  std::string error;
  if (!formation.IsValid(&error)) {
    // Point at the key that holds the fault; the message says which field.
    // (ConfigNode wraps a YAML::Node, whose assignment rebinds content: never reassign one.)
    std::string message = error;
    for (size_t pos = message.find("nominal_m"); pos != std::string::npos; pos = message.find("nominal_m")) {
      message.replace(pos, std::string("nominal_m").size(), "nominal_positions");
    }
    if (error.rfind("weights:", 0) == 0) radio.Required("graph").Fail("stress " + message);
    if (error.rfind("leaders:", 0) == 0) radio.FailAt("leaders", message);
    if (error.rfind("nominal_m:", 0) == 0) {
      section.Required("nominal_positions").Fail(message.substr(std::string("nominal_positions: ").size()));
    }
    section.FailAt("equilibrium_tolerance_m", message);
  }
  formation_ = std::make_unique<StressFormation>(formation);
}

void AffineFormationBuilder::ReadFollowerLaw(const ConfigNode& section) {
  const ConfigNode follower = section.Optional("follower");
  std::string error;
  for (int f : formation_->followers()) {
    AffineFollowerParams check = follower_;
    check.neighbours = formation_->Neighbours(f);
    if (!check.IsValid(&error)) {
      (follower.IsDefined() ? follower : section).Fail("follower " + std::to_string(f) + ": " + error);
    }
  }
}

void AffineFormationBuilder::ReadMetrics(const ConfigNode& section, const Section& fields) {
  metrics_ = fields.metrics;
  metrics_.nominal_m = formation_->nominal_m();
  metrics_.leaders = formation_->leaders();
  const ConfigNode metrics = section.Optional("metrics");
  if (!metrics.IsDefined()) return;
  if (metrics.Has(AffineFormationMetricsParams::kObstaclePairsKey)) {
    const ConfigNode pairs = metrics.Required(AffineFormationMetricsParams::kObstaclePairsKey);
    if (!pairs.IsSequence()) pairs.Fail("expected a list of [id, id] obstacle pairs");
    for (size_t k = 0; k < pairs.size(); ++k) {
      const ConfigNode pair = pairs[k];
      if (!pair.IsSequence() || pair.size() != 2) {
        pair.Fail("expected two obstacle ids [a, b] (their positions in the run config's obstacles list)");
      }
      metrics_.obstacle_pairs.push_back({pair[0].AsInt32(), pair[1].AsInt32()});
    }
  }
  std::string error;
  if (!metrics_.IsValid(&error)) metrics.FailAtField(error);
}

std::unique_ptr<agents::Robot> AffineFormationBuilder::MakeRobot(int robot_id,
                                                                 const agents::RobotParams& params) const {
  if (formation_->IsLeader(robot_id)) {
    AffineLeaderParams leader = leader_;
    leader.nominal_m = formation_->nominal_m().at(static_cast<size_t>(robot_id));
    return std::make_unique<AffineLeaderRobot>(robot_id, params, leader);
  }
  AffineFollowerParams follower = follower_;
  follower.neighbours = formation_->Neighbours(robot_id);
  return std::make_unique<AffineFollowerRobot>(robot_id, params, hrvo_, follower);
}

std::unique_ptr<agents::ExperimentMetrics> AffineFormationBuilder::MakeMetrics() const {
  return std::make_unique<AffineFormationMetrics>(metrics_);
}

std::vector<std::vector<Eigen::Vector2d>> AffineFormationBuilder::GoalsToDraw() const {
  // Where the maneuver leaves each robot's nominal position at its end.
  const AffineManeuver maneuver(maneuver_);
  std::vector<std::vector<Eigen::Vector2d>> goals;
  for (const Eigen::Vector2d& nominal : formation_->nominal_m()) {
    goals.push_back({maneuver.Target(nominal, static_cast<double>(maneuver.last_step()))});
  }
  return goals;
}

}  // namespace dream::affine_formation
