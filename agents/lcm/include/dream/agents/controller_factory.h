#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dream/agents/controller.h"
#include "dream/config/config_node.h"

namespace dream::agents {

/// Builds a robot's controller from the `controller:` section of a run
/// config. The section's `kind` names the controller; each kind reads its own
/// keys. To add a controller, add a kind here (see docs/writing-a-controller.md).
class ControllerFactory {
 public:
  /// Kinds this factory knows, for error messages and --help.
  static std::vector<std::string> Kinds();

  /// @param section the `controller:` mapping.
  /// @param num_robots robots in the run, to check per-robot lists.
  /// @throws config::ConfigError naming the key and value when the section is
  ///         invalid or names an unknown kind.
  ControllerFactory(const config::ConfigNode& section, int num_robots);

  /// A new controller for `robot_id` (0 <= robot_id < num_robots).
  std::unique_ptr<Controller> Make(int robot_id) const;

 private:
  config::ConfigNode section_;
  std::string kind_;
  int num_robots_;
};

}  // namespace dream::agents
