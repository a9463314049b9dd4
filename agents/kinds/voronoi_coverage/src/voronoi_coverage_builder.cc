#include "dream/voronoi_coverage/voronoi_coverage_builder.h"
#include "dream/kind_api/field_reader.h"

namespace dream::voronoi_coverage {
kind_api::AgentPartsConfig VoronoiCoverageBuilder::DefaultParts(int num_robots) {
  kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::Defaults(num_robots);
  kind_api::SensorConfig obstacle =
      kind_api::SensorConfig::Every(kind_api::SensorConfig::Kind::kObstacle, num_robots, 1);
  obstacle.obstacle.range_m = 1.0;
  parts.sensors.push_back(obstacle);
  parts.radio = kind_api::RadioConfig::Every(kind_api::RadioConfig::Kind::kRange, num_robots, 3);
  parts.radio.range_m = 2.0;
  return parts;
}

VoronoiCoverageBuilder::VoronoiCoverageBuilder(const config::ConfigNode& section, int num_robots) {
  Section fields;
  kind_api::ReadFields(section, num_robots, &fields);
  params_ = fields.robot;
  std::string error;
  if (!params_.IsValid(&error)) section.FailAtField(error);
  metrics_ = fields.metrics;
  metrics_.arena_min_m = params_.cell.arena_min_m;
  metrics_.arena_max_m = params_.cell.arena_max_m;
  metrics_.step_s = params_.step_s;
  if (!metrics_.IsValid(&error)) section.FailAtField(error);
}

std::unique_ptr<agents::Robot> VoronoiCoverageBuilder::MakeRobot(int robot_id,
                                                                 const agents::RobotParams& params) const {
  return std::make_unique<VoronoiCoverageRobot>(robot_id, params, params_);
}

std::unique_ptr<agents::ExperimentMetrics> VoronoiCoverageBuilder::MakeMetrics() const {
  return std::make_unique<VoronoiCoverageMetrics>(metrics_);
}

}  // namespace dream::voronoi_coverage
