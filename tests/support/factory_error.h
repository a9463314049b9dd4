#pragma once

#include <memory>
#include <string>
#include <utility>

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/controller_registry.h"
#include "dream/config/config_error.h"
#include "dream/run_config/run_config.h"

namespace dream::agents::testing {

/// The error of building a ControllerFactory for `config` ("" when it builds),
/// for tests of the messages a bad controller section gets.
inline std::string FactoryErrorOf(const run_config::RunConfig& config) {
  try {
    agent_host::ControllerFactory factory(config);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

/// The same with the kinds of `registry`.
inline std::string FactoryErrorOf(std::shared_ptr<const agent_host::ControllerRegistry> registry,
                                  const run_config::RunConfig& config) {
  try {
    agent_host::ControllerFactory factory(config, std::move(registry));
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace dream::agents::testing
