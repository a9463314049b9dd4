#include "dream/workflows/sweep_run_result.h"

#include <map>

#include "dream/session/run_exit_code.h"
#include "dream/world/printf_text.h"

namespace dream::workflows {
namespace {

/// Why `summary` is not `run`'s own (another seed's, another run's, or
/// without a run id); empty when it is.
std::string OtherRunsSummary(const SweepPlan::Run& run, const node::RunSummary& summary) {
  if (!summary.Has("seed") || summary.seed != run.seed) {
    return "summary.json is not this run's: its seed is " +
           (summary.Has("seed") ? std::to_string(summary.seed) : std::string("missing")) + ", the run's " +
           std::to_string(run.seed);
  }
  const std::string& name = summary.run;
  const std::string suffix = "_" + run.name;
  const bool names_run = name == run.name || (name.size() > suffix.size() &&
                                              name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0);
  if (!names_run)
    return "summary.json is not this run's: it is run '" + name.substr(0, 80) + "'s, not " + run.name + "'s";
  if (summary.run_id.empty()) return "summary.json names no run_id";
  return {};
}

SweepRunResult WithoutResult(const SweepPlan::Run& run, SweepRunResult::Status status, const std::string& why) {
  SweepRunResult result;
  result.run = run;
  result.status = status;
  result.problem = why;
  return result;
}

}  // namespace

SweepRunResult SweepRunResult::Judge(const SweepPlan::Run& run, int exit_code, bool timed_out, double wall_time_s,
                                     const std::optional<node::RunSummary>& summary, const std::string& failure_hint,
                                     const std::string& summary_problem) {
  SweepRunResult result;
  result.run = run;
  result.exit_code = exit_code;
  result.wall_time_s = wall_time_s;
  result.has_summary = summary.has_value();
  if (summary) {
    result.run_id = summary->run_id;
    if (summary->Has("end")) result.end = summary->end;
    if (summary->Has("verdict")) result.verdict = summary->verdict;
    result.steps = summary->steps;
    result.violations = summary->violations;
    const nlohmann::ordered_json& metrics = summary->metrics;
    if (metrics.is_object() && metrics.contains("min_pairwise_distance_m") &&
        metrics["min_pairwise_distance_m"].is_number()) {
      result.min_distance_m = metrics["min_pairwise_distance_m"].get<double>();
    }
    result.goal = session::ExperimentGoal::Judge(*summary);
  }

  const std::string hint = failure_hint.empty() ? std::string() : ": " + failure_hint;
  if (timed_out) {
    result.problem = "timed out after " + world::PrintfText("%.0f", wall_time_s) + " s";
  } else if (exit_code == session::kExitInterrupted) {
    result.status = Status::kInterrupted;
    result.problem = "interrupted";
  } else if (exit_code < 0) {
    result.problem = failure_hint.empty() ? std::string("did not start") : failure_hint;
  } else if (!session::RanToAVerdict(exit_code)) {
    // dream run: 1 config, 4 did not finish (3 rejected, 5 not ready: it ran); above 128 a signal killed it.
    result.problem = (exit_code > 128 ? "killed by signal " + std::to_string(exit_code - 128)
                                      : "exit " + std::to_string(exit_code)) +
                     hint;
  } else if (!result.has_summary) {
    result.problem = "exit " + std::to_string(exit_code) + " but no readable summary.json" +
                     (summary_problem.empty() ? std::string() : " (" + summary_problem + ")");
  } else if (const std::string other = OtherRunsSummary(run, *summary); !other.empty()) {
    result.problem = other;
  } else if (result.end != node::RunOutcome::End::kFinished) {
    result.problem = std::string("run ended '") + (result.end ? node::EndName(*result.end) : "") + "'" + hint;
  } else {
    result.status = Status::kRan;
  }
  // Without a goal of its own a run can be clean but never a success.
  result.success = result.status == Status::kRan && result.verdict != world::RunVerdict::kRejected &&
                   result.collisions() == 0 && result.goal.has_criterion && result.goal.met;
  return result;
}

SweepRunResult SweepRunResult::NotRun(const SweepPlan::Run& run, const std::string& why) {
  return WithoutResult(run, Status::kNotRun, why);
}

SweepRunResult SweepRunResult::LostRun(const SweepPlan::Run& run, const std::string& why) {
  return WithoutResult(run, Status::kFailed, why);
}

void SweepRunResult::RefuseSharedRunIds(std::vector<SweepRunResult>& results) {
  std::map<std::string, size_t> first_with_id;
  for (size_t i = 0; i < results.size(); ++i) {
    if (results[i].run_id.empty()) continue;
    const auto [first, inserted] = first_with_id.emplace(results[i].run_id, i);
    if (inserted) continue;
    for (size_t copy : {first->second, i}) {
      SweepRunResult& result = results[copy];
      const SweepRunResult& other = results[copy == i ? first->second : i];
      result.status = Status::kFailed;
      result.success = false;
      result.problem =
          "summary.json has the run id " + result.run_id + " of run " + other.run.name + " too: one is a copy";
    }
  }
}

std::string SweepRunResult::OutcomeText() const {
  if (status == Status::kInterrupted) return "interrupted";
  if (status == Status::kNotRun) return "not run (" + problem + ")";
  if (status == Status::kFailed) return "failed to run (" + problem + ")";
  if (success) return "success";
  std::string why;
  auto add = [&why](const std::string& part) { why += (why.empty() ? "" : "; ") + part; };
  if (violations.collision_errors > 0) add(std::to_string(violations.collision_errors) + " collision errors");
  if (violations.obstacle_collisions > 0) {
    add(std::to_string(violations.obstacle_collisions) + " obstacle collisions");
  }
  if (violations.boundary_errors > 0) add(std::to_string(violations.boundary_errors) + " boundary errors");
  if (verdict == world::RunVerdict::kRejected && why.empty()) add("rejected by the Robotarium checks");
  if (!goal.has_criterion) return why.empty() ? "no goal declared" : "no goal declared (" + why + ")";
  if (!goal.met) add(goal.detail);
  return "no success (" + why + ")";
}

std::string SweepRunResult::ShortOutcomeText() const {
  if (status == Status::kRan && !success && !goal.has_criterion) return "no goal declared";
  if (status == Status::kRan) return success ? "success" : "no success";
  return OutcomeText();
}

}  // namespace dream::workflows
