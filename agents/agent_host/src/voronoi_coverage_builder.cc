#include "dream/agent_host/voronoi_coverage_builder.h"

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
  (void)num_robots;
  agents::VoronoiCellParams& cell = params_.cell;
  cell.disc_radius_m = section.GetDouble("disc_radius_m", cell.disc_radius_m);
  cell.disc_sides = section.GetInt32("disc_sides", cell.disc_sides);
  cell.wall_margin_m = section.GetDouble("wall_margin_m", cell.wall_margin_m);
  cell.robot_buffer_m = section.GetDouble("robot_buffer_m", cell.robot_buffer_m);
  cell.obstacle_buffer_m = section.GetDouble("obstacle_buffer_m", cell.obstacle_buffer_m);
  params_.gain = section.GetDouble("gain", params_.gain);
  params_.max_speed_mps = section.GetDouble("max_speed_mps", params_.max_speed_mps);
  params_.tolerance_m = section.GetDouble("tolerance_m", params_.tolerance_m);
  params_.done_after_still_steps =
      section.GetInt32("done_after_still_steps", params_.done_after_still_steps);
  params_.radio_rounds_before_moving =
      section.GetInt32("radio_rounds_before_moving", params_.radio_rounds_before_moving);
  std::string error;
  if (!params_.IsValid(&error)) section.FailAtField(error);

  metrics_.arena_min_m = cell.arena_min_m;
  metrics_.arena_max_m = cell.arena_max_m;
  metrics_.step_s = params_.step_s;
  metrics_.sample_steps = section.GetInt32("coverage_sample_steps", metrics_.sample_steps);
  if (metrics_.sample_steps < 1) {
    section.Required("coverage_sample_steps").Fail("must be >= 1, got " + std::to_string(metrics_.sample_steps));
  }
  metrics_.still_speed_mps = section.GetDouble("still_speed_mps", metrics_.still_speed_mps);
  metrics_.still_window_steps = section.GetInt32("still_window_steps", metrics_.still_window_steps);
  if (!metrics_.IsValid(&error)) section.FailAtField(error);
}

std::unique_ptr<agents::Robot> VoronoiCoverageBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  return std::make_unique<agents::VoronoiCoverageRobot>(robot_id, params, params_);
}

std::unique_ptr<agents::ExperimentMetrics> VoronoiCoverageBuilder::MakeMetrics() const {
  return std::make_unique<agents::VoronoiCoverageMetrics>(metrics_);
}

}  // namespace dream::agent_host
