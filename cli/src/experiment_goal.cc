#include "experiment_goal.h"

#include <cstdio>

namespace dream::cli {
namespace {

double Number(const nlohmann::json& object, const std::string& key, double fallback) {
  if (!object.is_object()) return fallback;
  const auto it = object.find(key);
  return it != object.end() && it->is_number() ? it->get<double>() : fallback;
}

std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g m", value);
  return text;
}

}  // namespace

ExperimentGoal ExperimentGoal::Judge(const nlohmann::json& summary) {
  ExperimentGoal goal;
  const nlohmann::json metrics =
      summary.is_object() && summary.contains("metrics") ? summary["metrics"] : nlohmann::json();
  if (metrics.is_object() && metrics.contains("kind") && metrics["kind"].is_string()) goal.kind = metrics["kind"];
  goal.has_criterion = true;
  // Each step metric is -1 (or missing) until the goal is reached.
  auto by_step = [&](const char* key, const std::string& met_text, const std::string& missed_text) {
    goal.completion_step = static_cast<long long>(Number(metrics, key, -1.0));
    goal.met = goal.completion_step >= 0;
    goal.detail = goal.met ? met_text : missed_text;
  };
  if (goal.kind == "go_to_goal") {
    by_step("all_arrived_step", "all at their goals",
            "not all at their goals, worst " + Metres(Number(metrics, "final_max_goal_error_m", -1.0)));
  } else if (goal.kind == "hrvo_circle") {
    int formations = 0;
    for (auto it = metrics.begin(); it != metrics.end(); ++it) {
      const std::string& key = it.key();
      if (key.rfind("formation_", 0) == 0 && key.size() > 15 &&
          key.compare(key.size() - 15, 15, "_completed_step") == 0) {
        ++formations;
      }
    }
    const int completed = static_cast<int>(Number(metrics, "formations_completed", 0.0));
    const std::string text = std::to_string(completed) + " of " + std::to_string(formations) + " formations";
    by_step("all_formations_completed_step", text, text);
  } else if (goal.kind == "line_deployment") {
    by_step("converged_step", "line converged",
            "line not converged: straightness " + Metres(Number(metrics, "final_line_straightness_error_m", -1.0)) +
                ", spacing " + Metres(Number(metrics, "final_spacing_error_m", -1.0)));
  } else if (goal.kind == "voronoi_coverage") {
    by_step("settled_step", "settled", "not settled");
    if (!goal.met) {
      // Blocks that move to the last step keep the robots giving way, so they
      // never settle; coverage then means the cost fell and kept falling.
      const double initial = Number(metrics, "coverage_cost_initial_m4", -1.0);
      const double final_cost = Number(metrics, "coverage_cost_final_m4", -1.0);
      const double rise = Number(metrics, "coverage_cost_max_rise_m4", -1.0);
      char text[96];
      std::snprintf(text, sizeof(text), "cost %.3g -> %.3g m^4, largest rise %.2g", initial, final_cost, rise);
      goal.met = initial > 0.0 && final_cost >= 0.0 && rise >= 0.0 && final_cost <= 0.5 * initial &&
                 rise <= 0.01 * initial;
      goal.detail = std::string(goal.met ? "covering, not settled: " : "not settled: ") + text;
    }
  } else if (goal.kind == "affine_formation") {
    const double worst_m = Number(metrics, "max_follower_error_after_convergence_m", -1.0);
    const double tolerance_m = Number(metrics, "follower_error_tolerance_m", -1.0);
    goal.met = worst_m >= 0.0 && tolerance_m > 0.0 && worst_m <= tolerance_m;
    goal.completion_step = static_cast<long long>(Number(metrics, "settled_step", -1.0));
    goal.detail = "worst follower error " + Metres(worst_m) + (goal.met ? " <= " : " > ") + Metres(tolerance_m);
  } else {
    // A kind without a criterion here (e.g. an out-of-tree controller): the
    // run's own "every robot reported done" is its completion.
    goal.has_criterion = false;
    goal.met = true;
    goal.detail = "no goal defined for this kind";
    const double robots = Number(summary, "robots", -1.0);
    const nlohmann::json done =
        summary.is_object() && summary.contains("robots_done") ? summary["robots_done"] : nlohmann::json();
    const double done_count =
        done.is_array() ? static_cast<double>(done.size()) : (done.is_number() ? done.get<double>() : -2.0);
    if (robots > 0 && done_count == robots)
      goal.completion_step = static_cast<long long>(Number(summary, "steps", -1.0));
  }
  return goal;
}

std::optional<sim::VerdictReason> ExperimentGoal::Reason() const {
  if (!has_criterion || met) return std::nullopt;
  return sim::VerdictReason{"goal", sim::RunVerdict::kNotReady,
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
  return json;
}

}  // namespace dream::cli
