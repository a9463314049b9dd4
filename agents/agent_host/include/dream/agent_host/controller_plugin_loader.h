#pragma once

#include <string>

#include "dream/config/config_node.h"
#include "dream/config/controller_config.h"

namespace dream::agent_host {

/// Loads the controller plugins a run config names (`plugins:`) and adds
/// their kinds to ControllerRegistry::Global(). A file is loaded once per
/// process however many configs name it, and never unloaded: its code builds
/// and runs the agents.
class ControllerPluginLoader {
 public:
  /// Every plugin of `config`, in order.
  /// @throws config::ConfigError "FILE:LINE: plugins[i]: PATH: reason" when a
  ///         file is missing, cannot be loaded (with the loader's message),
  ///         lacks an entry point, links another copy of the dream libraries,
  ///         was built for another plugin API version, or registers a kind
  ///         that exists already.
  static void LoadAll(const config::ControllerConfig& config);

  /// The plugin at `path` (absolute); errors are reported at `entry`.
  static void Load(const std::string& path, const config::ConfigNode& entry);
};

}  // namespace dream::agent_host
