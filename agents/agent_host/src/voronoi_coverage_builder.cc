#include "dream/agent_host/voronoi_coverage_builder.h"
#include "dream/agent_host/field_reader.h"

namespace dream::agent_host {
AgentPartsConfig VoronoiCoverageBuilder::DefaultParts(int num_robots) {
  AgentPartsConfig parts = AgentPartsConfig::Defaults(num_robots);
  SensorConfig obstacle = SensorConfig::Every(SensorConfig::Kind::kObstacle, num_robots, 1);
  obstacle.obstacle.range_m = 1.0;
  parts.sensors.push_back(obstacle);
  parts.radio = RadioConfig::Every(RadioConfig::Kind::kRange, num_robots, 3);
  parts.radio.range_m = 2.0;
  return parts;
}

VoronoiCoverageBuilder::VoronoiCoverageBuilder(const config::ConfigNode& section, int num_robots) {
  Section fields;
  ReadFields(section, num_robots, &fields);
  params_ = fields.robot;
  std::string error;
  if (!params_.IsValid(&error)) section.FailAtField(error);
  metrics_ = fields.metrics;
  metrics_.arena_min_m = params_.cell.arena_min_m;
  metrics_.arena_max_m = params_.cell.arena_max_m;
  metrics_.step_s = params_.step_s;
  if (!metrics_.IsValid(&error)) section.FailAtField(error);
}

std::unique_ptr<agents::Robot> VoronoiCoverageBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  return std::make_unique<agents::VoronoiCoverageRobot>(robot_id, params, params_);
}

std::unique_ptr<agents::ExperimentMetrics> VoronoiCoverageBuilder::MakeMetrics() const {
  return std::make_unique<agents::VoronoiCoverageMetrics>(metrics_);
}

}  // namespace dream::agent_host
