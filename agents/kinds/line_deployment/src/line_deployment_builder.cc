#include "dream/line_deployment/line_deployment_builder.h"
#include "dream/kind_api/field_reader.h"

#include "dream/kind_api/hrvo_config.h"
#include "dream/line_deployment/line_formation_metrics.h"

namespace dream::line_deployment {

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

kind_api::AgentPartsConfig LineDeploymentBuilder::DefaultParts(int num_robots) {
  kind_api::AgentPartsConfig parts = kind_api::AgentPartsConfig::ThesisHrvoParts(num_robots);
  // The thesis found a 1 s radio period slowed convergence a lot; 10 steps is 0.33 s.
  parts.radio = kind_api::RadioConfig::Every(kind_api::RadioConfig::Kind::kGraph, num_robots, 10);
  if (num_robots == 6) {
    parts.radio.graph = ThesisAdjacency();
  } else {
    parts.radio.graph = Eigen::MatrixXd::Zero(num_robots, num_robots);
    for (int i = 0; i + 1 < num_robots; ++i) parts.radio.graph(i, i + 1) = parts.radio.graph(i + 1, i) = 1.0;
  }
  return parts;
}

LineDeploymentBuilder::LineDeploymentBuilder(const config::ConfigNode& section, int num_robots) {
  Section fields;
  kind_api::ReadFields(section, num_robots, &fields);
  params_ = fields.robot;
  std::string error;
  if (!params_.IsValid(&error)) section.FailAtField(error);
  converged_m_ = fields.converged_m;
  hrvo_ = fields.hrvo;
  if (!hrvo_.IsValid(&error)) section.Required("hrvo").FailAtField(error);
}

std::unique_ptr<agents::Robot> LineDeploymentBuilder::MakeRobot(int robot_id, const agents::RobotParams& params) const {
  return std::make_unique<LineDeploymentRobot>(robot_id, params, hrvo_, params_);
}

std::unique_ptr<agents::ExperimentMetrics> LineDeploymentBuilder::MakeMetrics() const {
  // Eq. 3.7 as printed converges to x_i = c - id_i d: ids descend along x.
  return std::make_unique<LineFormationMetrics>(-params_.spacing_m, converged_m_);
}

}  // namespace dream::line_deployment
