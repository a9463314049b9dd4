#include "dream/agent_host/line_deployment_builder.h"

#include "dream/agent_host/hrvo_config.h"
#include "dream/agents/experiments/line_formation_metrics.h"

namespace dream::agent_host {

Eigen::MatrixXd LineDeploymentBuilder::ThesisAdjacency() {
  Eigen::MatrixXd a(6, 6);
  a << 0, 1, 1, 0, 0, 0,  //
      1, 0, 1, 0, 1, 0,   //
      1, 1, 0, 1, 0, 0,   //
      0, 0, 1, 0, 1, 1,   //
      0, 1, 0, 1, 0, 1,   //
      0, 0, 0, 1, 1, 0;
  return a;
}

AgentPartsConfig LineDeploymentBuilder::DefaultParts(int num_robots) {
  AgentPartsConfig parts = AgentPartsConfig::ThesisHrvoParts(num_robots);
  // The thesis found a 1 s radio period slowed convergence a lot; 10 steps is 0.33 s.
  parts.radio = RadioConfig::Every(RadioConfig::Kind::kGraph, num_robots, 10);
  if (num_robots == 6) {
    parts.radio.graph = ThesisAdjacency();
  } else {
    parts.radio.graph = Eigen::MatrixXd::Zero(num_robots, num_robots);
    for (int i = 0; i + 1 < num_robots; ++i) parts.radio.graph(i, i + 1) = parts.radio.graph(i + 1, i) = 1.0;
  }
  return parts;
}

LineDeploymentBuilder::LineDeploymentBuilder(const config::ConfigNode& section, int num_robots) {
  (void)num_robots;
  params_.spacing_m = section.GetDouble("spacing_m", params_.spacing_m);
  params_.gain = section.GetDouble("gain", params_.gain);
  params_.max_speed_mps = section.GetDouble("max_speed_mps", params_.max_speed_mps);
  params_.tolerance_m = section.GetDouble("tolerance_m", params_.tolerance_m);
  params_.resume_m = section.GetDouble("resume_m", params_.resume_m);
  params_.hold_avoid_range_m = section.GetDouble("hold_avoid_range_m", params_.hold_avoid_range_m);
  params_.arena_margin_m = section.GetDouble("arena_margin_m", params_.arena_margin_m);
  const long long settle = section.GetInt("settle_updates", params_.settle_updates);
  if (settle < 1 || settle > 100000) {
    section.Required("settle_updates").Fail("must be in 1..100000, got " + std::to_string(settle));
  }
  params_.settle_updates = static_cast<int>(settle);
  std::string error;
  if (!params_.IsValid(&error)) section.FailAtField(error);
  converged_m_ = section.GetDouble("converged_m", converged_m_);
  if (!(converged_m_ > 0.0)) section.Required("converged_m").Fail("must be > 0, got " + std::to_string(converged_m_));
  hrvo_ = ReadHrvoRobotParams(section);
}

std::unique_ptr<agents::Robot> LineDeploymentBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  return std::make_unique<agents::LineDeploymentRobot>(robot_id, params, hrvo_, params_);
}

std::unique_ptr<agents::ExperimentMetrics> LineDeploymentBuilder::MakeMetrics() const {
  // Eq. 3.7 as printed converges to x_i = c - id_i d: ids descend along x.
  return std::make_unique<agents::LineFormationMetrics>(-params_.spacing_m, converged_m_);
}

}  // namespace dream::agent_host
