#include "dream/bridge/metrics_json.h"

#include <algorithm>

#include "dream/agent_host/controller_factory.h"
#include "dream/agent_host/log_metrics.h"
#include "dream/kind_api/controller_kind.h"
#include "dream/kind_api/run_poses.h"

namespace dream::bridge {
namespace {

// The log's poses as plain values, what a kind's own metrics read.
kind_api::RunPoses RunPosesOf(const run_log::RunLog& log) {
  kind_api::RunPoses poses;
  poses.steps.reserve(log.poses().size());
  for (const robot_poses_t& message : log.poses()) {
    kind_api::RunPoses::Step& step = poses.steps.emplace_back();
    step.step = message.step;
    const size_t robots = std::min({static_cast<size_t>(std::max(message.num_robots, 0)), message.x.size(),
                                    message.y.size(), message.theta.size()});
    step.poses.reserve(robots);
    for (size_t i = 0; i < robots; ++i) step.poses.emplace_back(message.x[i], message.y[i], message.theta[i]);
  }
  return poses;
}

}  // namespace

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
                                   const run_log::RunLog& log, const std::string& runtime_dir) {
  nlohmann::ordered_json json = MetricsJson(factory, log);
  // A kind may compute metrics of its own besides its builder's (the python kind: in the Python runtime).
  const kind_api::ControllerKind& kind = factory.registered_kind();
  if (json.contains("error") || runtime_dir.empty() || !kind.own_metrics) return json;
  try {
    const nlohmann::json own = kind.own_metrics(config, RunPosesOf(log), runtime_dir);
    if (own.contains("goal") && own["goal"].is_object()) json["goal"] = own["goal"];
    if (own.contains("goal_points") && own["goal_points"].is_array() && !own["goal_points"].empty()) {
      json["goal_points"] = own["goal_points"];
    }
    if (own.contains("metrics") && own["metrics"].is_object()) {
      for (const auto& [name, value] : own["metrics"].items()) {
        if (!json.contains(name)) json[name] = value;
      }
    }
  } catch (const std::exception& e) {
    json["error"] = e.what();
  }
  return json;
}

}  // namespace dream::bridge
