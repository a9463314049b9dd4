#pragma once

#include <string>

#include "dream/config/controller_config.h"

namespace dream::python {

/// The controller spec of a run whose `controller:` is of kind python: what
/// the Python runtime needs to build every robot's agent, as JSON (format 1,
/// docs/python-runtime-contract.md): run name, config file, robot count,
/// seed, the module's absolute path and the class, the common parts as
/// checked here (one value per robot), and the section's other keys with the
/// line each is on, for the Python side to check against the class's KEYS.
/// The same text feeds the Python agents (dream::python_host) and a
/// submission of the controller strategy (bridge), so both build the same
/// agents.
/// The python kind's ControllerKind::runtime_spec.
/// @throws config::ConfigError as ControllerFactory does, or when the kind is
///         not python.
std::string PythonControllerSpecJson(const config::ControllerConfig& config);

}  // namespace dream::python
