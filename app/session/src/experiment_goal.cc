#include "dream/session/experiment_goal.h"

namespace dream::session {
namespace {

double Number(const nlohmann::json& object, const std::string& key, double fallback) {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : fallback;
}

}  // namespace

ExperimentGoal ExperimentGoal::Judge(const node::RunSummary& summary) {
  ExperimentGoal goal;
  const nlohmann::json metrics = summary.metrics;  // the kind's section, as it wrote it
  if (metrics.is_object() && metrics.contains("kind") && metrics["kind"].is_string()) goal.kind = metrics["kind"];
  // The kind's own rule wrote metrics.goal (ExperimentMetrics::JudgeGoal).
  const nlohmann::json judged = metrics.is_object() && metrics.contains("goal") ? metrics["goal"] : nlohmann::json();
  if (metrics.is_object() && metrics.contains("error")) {
    goal.has_criterion = true;
    goal.judge_error = metrics["error"].is_string() ? metrics["error"].get<std::string>() : "metrics.error";
    if (goal.judge_error.empty()) goal.judge_error = "metrics.error";
    goal.detail = "no metrics: " + goal.judge_error;
    return goal;
  }
  if (judged.is_object()) {
    goal.has_criterion = true;
    goal.met = judged.contains("met") && judged["met"].is_boolean() && judged["met"].get<bool>();
    goal.completion_step = static_cast<long long>(Number(judged, "completion_step", -1.0));
    goal.detail =
        judged.contains("detail") && judged["detail"].is_string() ? judged["detail"].get<std::string>() : std::string();
    return goal;
  }
  // A kind without a rule of its own (e.g. a one-class plugin): the run's own
  // "every robot reported done" is its completion.
  goal.met = true;
  goal.detail = "no goal declared";
  const auto done_count = static_cast<int64_t>(summary.robots_done.size());
  if (summary.robots > 0 && summary.Has("robots_done") && done_count == summary.robots && summary.Has("steps")) {
    goal.completion_step = summary.steps;
  }
  return goal;
}

std::optional<world::VerdictReason> ExperimentGoal::Reason() const {
  if (!has_criterion || met) return std::nullopt;
  if (!judge_error.empty()) {
    return world::VerdictReason{
        "goal", world::RunVerdict::kNotReady,
        "the " + (kind.empty() ? std::string("run") : kind) + " experiment's goal could not be judged: " + judge_error,
        "fix the experiment's metrics or goal (its error above); dream render RUN --plot "
        "shows the run"};
  }
  return world::VerdictReason{"goal", world::RunVerdict::kNotReady,
                              "the " + kind + " experiment missed its goal: " + detail,
                              "summary.json metrics; dream render RUN --plot shows them over time"};
}

nlohmann::ordered_json ExperimentGoal::Json() const {
  nlohmann::ordered_json json;
  json["kind"] = kind;
  json["has_criterion"] = has_criterion;
  json["met"] = met;
  json["completion_step"] = completion_step;
  json["detail"] = detail;
  if (!judge_error.empty()) json["judge_error"] = judge_error;
  return json;
}

std::string ExperimentGoal::Text(const nlohmann::json& goal) {
  if (!goal.is_object()) return "none declared";
  const std::string detail = goal.value("detail", std::string());
  const std::string judge_error = goal.value("judge_error", std::string());
  if (!judge_error.empty()) return "could not be judged: " + judge_error;
  if (!goal.value("has_criterion", false)) return detail.empty() ? "none declared" : detail;
  if (goal.value("met", false)) {
    const long long step = goal.value("completion_step", -1LL);
    return "met" + (step >= 0 ? " at step " + std::to_string(step) : std::string()) +
           (detail.empty() ? "" : " (" + detail + ")");
  }
  return "missed" + (detail.empty() ? std::string() : " (" + detail + ")");
}

}  // namespace dream::session
