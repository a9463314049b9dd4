#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "dream/config/run_config.h"

namespace dream::agents {
class ControllerFactory;
}  // namespace dream::agents

namespace dream::bridge {

/// The experiment's metrics computed from a run log, as `dream run` puts
/// them under "metrics" in summary.json ({"kind": ..., values, steps,
/// series}); {"error": ...} when they cannot be computed.
nlohmann::ordered_json MetricsJson(const config::RunConfig& config, const std::string& log_path);

/// The same with the run's factory, when the caller has one already (so its
/// plugins are not loaded and its section not read again).
nlohmann::ordered_json MetricsJson(const agents::ControllerFactory& factory, const std::string& log_path);

}  // namespace dream::bridge
