#include "dream/agent_host/controller_factory.h"

#include <algorithm>
#include <stdexcept>

#include "dream/agent_host/controller_registry.h"
#include "dream/agents/framework/noise_source.h"
#include "dream/agents/framework/safety_metrics.h"
#include "dream/config/name_suggestion.h"

namespace dream::agent_host {
namespace {

// The built-in kinds, shared but not owned (they are never destroyed).
std::shared_ptr<const ControllerRegistry> BuiltInKinds() {
  return std::shared_ptr<const ControllerRegistry>(&ControllerRegistry::BuiltIns(), [](const ControllerRegistry*) {});
}

}  // namespace

std::vector<std::string> ControllerFactory::Kinds() { return ControllerRegistry::BuiltIns().Names(); }

ControllerFactory::ControllerFactory(const config::ControllerConfig& config)
    : ControllerFactory(config, ControllerRegistry::ForConfig(config)) {}

ControllerFactory::ControllerFactory(const config::ControllerConfig& config,
                                     std::shared_ptr<const ControllerRegistry> registry)
    : ControllerFactory(config.controller, config.num_robots, config.seed, std::move(registry)) {}

ControllerFactory::ControllerFactory(const config::ConfigNode& section, int num_robots, uint64_t run_seed)
    : ControllerFactory(section, num_robots, run_seed, BuiltInKinds()) {}

ControllerFactory::ControllerFactory(const config::ConfigNode& section, int num_robots, uint64_t run_seed,
                                     std::shared_ptr<const ControllerRegistry> registry)
    : registry_(std::move(registry)), num_robots_(num_robots), run_seed_(run_seed) {
  kind_ = section.Required("kind").AsString();
  const kind_api::ControllerKind* entry = registry_->Find(kind_);
  if (entry == nullptr) {
    const std::vector<std::string> kinds = registry_->Names();
    std::string known;
    for (const std::string& kind : kinds) known += (known.empty() ? "" : ", ") + kind;
    section.Required("kind").Fail("unknown controller kind '" + kind_ + "'" + config::DidYouMean(kind_, kinds) +
                                  "; known kinds: " + known + " (a plugin's kind needs the plugin under `plugins:`)");
  }
  std::vector<std::string> keys = {"kind", "robot", "sensors", "radio"};
  keys.insert(keys.end(), entry->keys.begin(), entry->keys.end());
  for (const std::string& key : entry->checks_own_keys ? std::vector<std::string>{} : section.Keys()) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string allowed;
    for (const std::string& k : keys) allowed += (allowed.empty() ? "" : ", ") + k;
    section.Optional(key).Fail("unknown key for kind " + kind_ + config::DidYouMean(key, keys) +
                               "; allowed keys here: " + allowed);
  }
  parts_ = kind_api::AgentPartsConfig::Read(section, num_robots, entry->default_parts(num_robots),
                                            entry->graph_must_connect);
  builder_ = entry->make_builder(section, num_robots);
  entry_ = entry;
}

ControllerFactory::~ControllerFactory() = default;

std::unique_ptr<agents::RobotAgent> ControllerFactory::Make(int robot_id) const {
  if (robot_id < 0 || robot_id >= num_robots_) {
    throw std::out_of_range("robot " + std::to_string(robot_id) + " is not in this run (robots 0.." +
                            std::to_string(num_robots_ - 1) + ")");
  }
  agents::RobotAgentSpec spec = parts_.MakeSpec(builder_->MakeRobot(robot_id, parts_.robot), run_seed_);
  return std::make_unique<agents::RobotAgent>(
      std::move(spec), agents::NoiseSource::MixSeed(run_seed_, static_cast<uint64_t>(robot_id), 0));
}

std::vector<std::unique_ptr<agents::ExperimentMetrics>> ControllerFactory::MakeMetrics() const {
  std::vector<std::unique_ptr<agents::ExperimentMetrics>> metrics;
  if (std::unique_ptr<agents::ExperimentMetrics> own = builder_->MakeMetrics()) metrics.push_back(std::move(own));
  metrics.push_back(std::make_unique<agents::SafetyMetrics>());
  return metrics;
}

}  // namespace dream::agent_host
