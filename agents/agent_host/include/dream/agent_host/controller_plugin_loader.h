#pragma once

#include <string>

#include "dream/agent_host/controller_plugin.h"
#include "dream/config/config_node.h"
#include "dream/config/controller_config.h"

namespace dream::agent_host {

class ControllerRegistry;

/// Loads the controller plugins a run config names (`plugins:`) and adds
/// their kinds to a registry (ControllerRegistry::ForConfig's). A file is
/// loaded into the process once however many configs name it, and never
/// unloaded: its code builds and runs the agents.
class ControllerPluginLoader {
 public:
  /// Every plugin of `config`, in order, its kinds added to `registry` (a
  /// plugin named twice adds its kinds once).
  /// @throws config::ConfigError "FILE:LINE: plugins[i]: PATH: reason" when a
  ///         file is missing, cannot be loaded (with the loader's message),
  ///         lacks an entry point, links another copy of the dream libraries,
  ///         was built for another plugin API version, or registers a kind
  ///         that exists already.
  static void AddKinds(const config::ControllerConfig& config, ControllerRegistry* registry);

 private:
  /// Loads the plugin at `path` (absolute) and checks it; its registration
  /// function. Errors are reported at `entry`.
  using Registration = RegisterControllersFunction;
  static Registration Load(const std::string& path, const config::ConfigNode& entry, void** handle);
};

}  // namespace dream::agent_host
