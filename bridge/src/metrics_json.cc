#include "dream/bridge/metrics_json.h"

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/log_metrics.h"
#include "dream/bridge/python_run_metrics.h"
#include "dream/kind_api/controller_kind.h"

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

nlohmann::ordered_json MetricsJson(const run_config::RunConfig& config, const agent_host::ControllerFactory& factory,
                                   const run_log::RunLog& log, const std::string& python_runtime_dir) {
  nlohmann::ordered_json json = MetricsJson(factory, log);
  // A kind whose robots run in the Python runtime has its own metrics and goal there.
  const kind_api::ControllerKind& kind = factory.registered_kind();
  if (json.contains("error") || python_runtime_dir.empty() ||
      kind.runtime != kind_api::ControllerKind::Runtime::kPython) {
    return json;
  }
  try {
    const nlohmann::json own = PythonRunMetrics::Compute(python_runtime_dir, kind.runtime_spec(config), log);
    if (own.contains("goal") && own["goal"].is_object()) json["goal"] = own["goal"];
    if (own.contains("goal_points") && own["goal_points"].is_array() && !own["goal_points"].empty()) {
      json["goal_points"] = own["goal_points"];
    }
    for (const auto& [name, value] : own["metrics"].items()) {
      if (!json.contains(name)) json[name] = value;
    }
  } catch (const std::exception& e) {
    json["error"] = e.what();
  }
  return json;
}

}  // namespace dream::bridge
