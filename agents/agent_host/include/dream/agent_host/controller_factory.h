#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dream/kind_api/agent_parts_config.h"
#include "dream/kind_api/controller_kind.h"
#include "dream/kind_api/experiment_builder.h"
#include "dream/agents/framework/robot_agent.h"
#include "dream/config/config_node.h"
#include "dream/config/controller_config.h"

namespace dream::agent_host {

class ControllerRegistry;

/// Builds every robot's agent, and the experiment's metrics, from the
/// `controller:` section of a run config. `kind` picks the experiment from
/// the factory's ControllerRegistry; the common keys (robot, sensors, radio) pick
/// the parts. To add an experiment, register its kind: a Robot subclass
/// alone (ControllerKind::OfRobot) or an ExperimentBuilder with metrics of
/// its own (ControllerKind::Of), built in (controller_registry.cc) or from a
/// plugin that the config names (see docs/writing-a-controller.md).
class ControllerFactory {
 public:
  /// The built-in kinds, for error messages and --help.
  static std::vector<std::string> Kinds();

  /// The factory of a run config's controller part (a RunConfig is one), with
  /// the kinds of ControllerRegistry::ForConfig(config): the built-in ones and
  /// those of the plugins it names. Then reads its `controller:` section.
  /// @throws config::ConfigError naming the key, and the plugin's path.
  explicit ControllerFactory(const config::ControllerConfig& config);
  /// The same with the kinds of `registry` (a test's own kinds, say).
  ControllerFactory(const config::ControllerConfig& config, std::shared_ptr<const ControllerRegistry> registry);

  /// A factory of the built-in kinds.
  /// @param run_seed seeds every sensor's noise and radio loss.
  /// @throws config::ConfigError naming the key and value when the section is
  ///         invalid or names an unknown kind.
  ControllerFactory(const config::ConfigNode& section, int num_robots, uint64_t run_seed);
  ~ControllerFactory();

  /// A new agent for `robot_id` (0 <= robot_id < num_robots).
  std::unique_ptr<agents::RobotAgent> Make(int robot_id) const;

  /// The experiment's own metrics (when its builder has any) followed by the
  /// common safety metrics.
  std::vector<std::unique_ptr<agents::ExperimentMetrics>> MakeMetrics() const;

  /// The kind's goal points per robot, for pictures (ExperimentBuilder::GoalsToDraw).
  std::vector<std::vector<Eigen::Vector2d>> GoalsToDraw() const { return builder_->GoalsToDraw(); }

  const std::string& kind() const { return kind_; }
  /// What the registry says of that kind (where its robots run, its file, ...).
  const kind_api::ControllerKind& registered_kind() const { return *entry_; }
  /// The robots' parts (timer, sensors, radio) as the config sets them.
  const kind_api::AgentPartsConfig& parts() const { return parts_; }

 private:
  ControllerFactory(const config::ConfigNode& section, int num_robots, uint64_t run_seed,
                    std::shared_ptr<const ControllerRegistry> registry);

  std::shared_ptr<const ControllerRegistry> registry_;  // holds the kind this factory builds
  std::string kind_;
  const kind_api::ControllerKind* entry_ = nullptr;  // in registry_
  int num_robots_;
  uint64_t run_seed_;
  kind_api::AgentPartsConfig parts_;
  std::unique_ptr<kind_api::ExperimentBuilder> builder_;
};

}  // namespace dream::agent_host
