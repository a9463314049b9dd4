#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "dream/run_config/run_config.h"
#include "dream/run_log/run_log.h"

namespace dream::agent_host {
class ControllerFactory;
}  // namespace dream::agent_host

namespace dream::bridge {

/// The experiment's metrics computed from a run's log (agent_host::MetricsFromLog),
/// as `dream run` puts them under "metrics" in summary.json ({"kind": ...,
/// "goal": ..., values, steps, series}); {"error": ...} when they cannot be
/// computed (also when the config's factory cannot be built).
nlohmann::ordered_json MetricsJson(const run_config::RunConfig& config, const run_log::RunLog& log);

/// The same with the run's factory, when the caller has one already (so its
/// plugins are not loaded and its section not read again).
nlohmann::ordered_json MetricsJson(const agent_host::ControllerFactory& factory, const run_log::RunLog& log);

/// The same, plus the metrics the run's kind computes itself
/// (ControllerKind::own_metrics: the python kind's class's figures, goal and
/// goal points, with the Python runtime in `runtime_dir`): its goal becomes
/// "goal", its goal points "goal_points", its figures join the others (never
/// replacing one). A kind without them, or an empty `runtime_dir`, adds
/// nothing; one whose computation fails gives "error".
nlohmann::ordered_json MetricsJson(const run_config::RunConfig& config, const agent_host::ControllerFactory& factory,
                                   const run_log::RunLog& log, const std::string& runtime_dir);

}  // namespace dream::bridge
