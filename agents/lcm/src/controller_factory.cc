#include "dream/agents/controller_factory.h"

#include <functional>
#include <initializer_list>
#include <stdexcept>

#include "dream/agents/affine_formation_builder.h"
#include "dream/agents/go_to_goal_builder.h"
#include "dream/agents/hrvo_circle_builder.h"
#include "dream/agents/line_deployment_builder.h"
#include "dream/agents/noise_source.h"
#include "dream/agents/safety_metrics.h"
#include "dream/agents/voronoi_coverage_builder.h"

namespace dream::agents {
namespace {

/// What an experiment kind brings: its own keys, its default parts, and how
/// to construct its builder.
struct KindEntry {
  const char* kind;
  std::vector<const char*> keys;
  std::function<AgentPartsConfig(int num_robots)> defaults;
  bool graph_must_connect;
  std::function<std::unique_ptr<ExperimentBuilder>(const config::ConfigNode&, int num_robots)> make;
};

const std::vector<KindEntry>& Registry() {
  static const std::vector<KindEntry> registry = {
      {GoToGoalBuilder::kKind, GoToGoalBuilder::Keys(), AgentPartsConfig::Defaults, false,
       [](const config::ConfigNode& s, int n) { return std::make_unique<GoToGoalBuilder>(s, n); }},
      // The followers need every leader's word: the role radio's graph must connect.
      {AffineFormationBuilder::kKind, AffineFormationBuilder::Keys(), AffineFormationBuilder::DefaultParts, true,
       [](const config::ConfigNode& s, int n) { return std::make_unique<AffineFormationBuilder>(s, n); }},
      {VoronoiCoverageBuilder::kKind, VoronoiCoverageBuilder::Keys(), VoronoiCoverageBuilder::DefaultParts, false,
       [](const config::ConfigNode& s, int n) { return std::make_unique<VoronoiCoverageBuilder>(s, n); }},
      {HrvoCircleBuilder::kKind, HrvoCircleBuilder::Keys(), HrvoCircleBuilder::DefaultParts, false,
       [](const config::ConfigNode& s, int n) { return std::make_unique<HrvoCircleBuilder>(s, n); }},
      // Consensus (eq. 3.7) needs a symmetric, connected graph.
      {LineDeploymentBuilder::kKind, LineDeploymentBuilder::Keys(), LineDeploymentBuilder::DefaultParts, true,
       [](const config::ConfigNode& s, int n) { return std::make_unique<LineDeploymentBuilder>(s, n); }},
  };
  return registry;
}

}  // namespace

std::vector<std::string> ControllerFactory::Kinds() {
  std::vector<std::string> kinds;
  for (const KindEntry& entry : Registry()) kinds.emplace_back(entry.kind);
  return kinds;
}

ControllerFactory::ControllerFactory(const config::ConfigNode& section, int num_robots, uint64_t run_seed)
    : num_robots_(num_robots), run_seed_(run_seed) {
  kind_ = section.Required("kind").AsString();
  for (const KindEntry& entry : Registry()) {
    if (kind_ != entry.kind) continue;
    std::vector<const char*> keys = {"kind", "robot", "sensors", "radio"};
    keys.insert(keys.end(), entry.keys.begin(), entry.keys.end());
    // RejectUnknownKeys takes an initializer list; check by hand to reuse its message.
    for (const std::string& key : section.Keys()) {
      bool known = false;
      std::string allowed;
      for (const char* k : keys) {
        known = known || key == k;
        allowed += (allowed.empty() ? "" : ", ") + std::string(k);
      }
      if (!known) section.Optional(key).Fail("unknown key for kind " + kind_ + "; allowed keys here: " + allowed);
    }
    parts_ = AgentPartsConfig::Read(section, num_robots, entry.defaults(num_robots), entry.graph_must_connect);
    builder_ = entry.make(section, num_robots);
    return;
  }
  std::string known;
  for (const std::string& kind : Kinds()) known += (known.empty() ? "" : ", ") + kind;
  section.Required("kind").Fail("unknown controller kind '" + kind_ + "'; known kinds: " + known);
}

ControllerFactory::~ControllerFactory() = default;

std::unique_ptr<RobotAgent> ControllerFactory::Make(int robot_id) const {
  if (robot_id < 0 || robot_id >= num_robots_) {
    throw std::out_of_range("robot " + std::to_string(robot_id) + " is not in this run (robots 0.." +
                            std::to_string(num_robots_ - 1) + ")");
  }
  RobotAgentSpec spec = parts_.MakeSpec(builder_->MakeRobot(robot_id, parts_.robot), run_seed_);
  return std::make_unique<RobotAgent>(std::move(spec),
                                      NoiseSource::MixSeed(run_seed_, static_cast<uint64_t>(robot_id), 0));
}

std::vector<std::unique_ptr<ExperimentMetrics>> ControllerFactory::MakeMetrics() const {
  std::vector<std::unique_ptr<ExperimentMetrics>> metrics;
  metrics.push_back(builder_->MakeMetrics());
  metrics.push_back(std::make_unique<SafetyMetrics>());
  return metrics;
}

}  // namespace dream::agents
