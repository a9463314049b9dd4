#pragma once

#include <memory>
#include <string>
#include <vector>

#include "dream/agent_host/controller_registry.h"
#include "dream/agents/framework/metrics_report.h"
#include "dream/run_config/run_config.h"
#include "dream/world/pose2.h"
#include "dream/node/run_outcome.h"
#include "dream/world/violation_counts.h"

namespace dream::agents::scenario {

/// What a headless run of an experiment produced.
struct ScenarioResult {
  node::RunOutcome outcome;
  world::ViolationCounts violations;
  MetricsReport metrics;
  std::vector<world::Pose2> final_poses;
  long bad_radio_messages = 0;
};

/// Runs `config` as `dream run` does (every agent and the simulator on one
/// memq bus, the log recorded), then computes the experiment's metrics from
/// the log, as the summary does. `log_name` names the temporary log.
/// `registry`: the kinds to build from (none: the built-in ones and the config's plugins').
ScenarioResult RunScenario(run_config::RunConfig config, const std::string& log_name,
                           std::shared_ptr<const agent_host::ControllerRegistry> registry = nullptr);

/// config/<name>.yaml in the source tree.
std::string ConfigPath(const std::string& name);

/// The metric `name`; NaN and a test failure when it is missing.
double Value(const ScenarioResult& run, const std::string& name);

}  // namespace dream::agents::scenario
