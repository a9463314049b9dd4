#include "dream/bridge/metrics_json.h"

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/log_metrics.h"

namespace dream::bridge {

nlohmann::ordered_json MetricsJson(const run_config::RunConfig& config, const run_log::RunLog& log) {
  try {
    return MetricsJson(agent_host::ControllerFactory(config), log);
  } catch (const std::exception& e) {
    nlohmann::ordered_json json;
    json["error"] = e.what();
    return json;
  }
}

nlohmann::ordered_json MetricsJson(const agent_host::ControllerFactory& factory, const run_log::RunLog& log) {
  nlohmann::ordered_json json;
  try {
    std::optional<agents::GoalJudgement> goal;
    const agents::MetricsReport report = agent_host::MetricsFromLog(factory, log, &goal);
    json["kind"] = factory.kind();
    if (goal) {
      // The kind's own success rule, in the standard form sweeps, export and the verdict read.
      json["goal"] = {{"met", goal->met}, {"completion_step", goal->completion_step}, {"detail", goal->detail}};
    }
    for (const auto& [name, value] : report.values) json[name] = value;
    for (const auto& [name, steps] : report.steps) json[name] = steps;
    for (const auto& [name, series] : report.series) {
      nlohmann::json points = nlohmann::json::array();
      for (const auto& [step, value] : series) points.push_back({step, value});
      json[name] = points;
    }
  } catch (const std::exception& e) {
    json["error"] = e.what();
  }
  return json;
}

}  // namespace dream::bridge
