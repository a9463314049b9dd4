#include "dream/workflows/sweep_table.h"

#include <algorithm>
#include <cstdio>

#include "dream/workflows/sweep_value_stats.h"

namespace dream::workflows {
namespace {

std::string Fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  return text;
}

std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string MarkdownCell(const std::string& text) {
  std::string cell;
  for (char c : text) {
    if (c == '|') {
      cell += "\\|";
    } else if (c == '\n' || c == '\r') {
      cell += ' ';
    } else {
      cell += c;
    }
  }
  return cell;
}

const char* StatusName(SweepRunResult::Status status) {
  switch (status) {
    case SweepRunResult::Status::kRan:
      return "ran";
    case SweepRunResult::Status::kInterrupted:
      return "interrupted";
    case SweepRunResult::Status::kNotRun:
      return "not run";
    default:
      return "failed";
  }
}

std::string StepOrEmpty(long long step, const std::string& none) { return step >= 0 ? std::to_string(step) : none; }

}  // namespace

SweepTable::SweepTable(std::vector<std::string> parameter_keys, size_t planned_runs)
    : keys_(std::move(parameter_keys)), planned_(planned_runs) {}

void SweepTable::Add(SweepRunResult result) {
  const auto at = std::upper_bound(results_.begin(), results_.end(), result.run.index,
                                   [](size_t index, const SweepRunResult& r) { return index < r.run.index; });
  results_.insert(at, std::move(result));
}

SweepSummary SweepTable::Summary() const {
  SweepSummary s;
  s.planned = planned_;
  s.listed = results_.size();
  long long completion_sum = 0;
  for (const SweepRunResult& r : results_) {
    switch (r.status) {
      case SweepRunResult::Status::kRan:
        ++s.ran;
        break;
      case SweepRunResult::Status::kFailed:
        ++s.failed;
        break;
      case SweepRunResult::Status::kInterrupted:
        ++s.interrupted;
        break;
      case SweepRunResult::Status::kNotRun:
        ++s.not_run;
        break;
    }
    if (r.success) ++s.succeeded;
    if (r.status == SweepRunResult::Status::kRan && !r.goal.has_criterion) ++s.without_goal;
    if (r.status == SweepRunResult::Status::kRan && r.goal.completion_step >= 0) {
      ++s.completed;
      completion_sum += r.goal.completion_step;
      s.completion_min =
          s.completion_min < 0 ? r.goal.completion_step : std::min(s.completion_min, r.goal.completion_step);
      s.completion_max = std::max(s.completion_max, r.goal.completion_step);
    }
    if (r.min_distance_m && (!s.has_min_distance || *r.min_distance_m < s.worst_min_distance_m)) {
      s.has_min_distance = true;
      s.worst_min_distance_m = *r.min_distance_m;
      s.worst_min_distance_run = r.run.name;
    }
    s.violations += r.violations;
  }
  const size_t judged = s.ran + s.failed;
  s.success_rate = judged > 0 ? static_cast<double>(s.succeeded) / static_cast<double>(judged) : 0.0;
  s.completion_mean = s.completed > 0 ? static_cast<double>(completion_sum) / static_cast<double>(s.completed) : 0.0;
  return s;
}

std::string SweepTable::Csv() const {
  std::string csv = "run,seed";
  for (const std::string& key : keys_) csv += "," + CsvField(key);
  csv +=
      ",status,success,exit_code,end,verdict,steps,completion_step,min_distance_m,boundary_errors,"
      "collision_errors,actuator_errors,obstacle_collisions,goal_met,goal,wall_time_s,problem\n";
  for (const SweepRunResult& r : results_) {
    csv += CsvField(r.run.name) + "," + std::to_string(r.run.seed);
    for (const auto& parameter : r.run.parameters) csv += "," + CsvField(parameter.second);
    csv += std::string(",") + StatusName(r.status) + "," + (r.success ? "true" : "false") + "," +
           std::to_string(r.exit_code) + "," + CsvField(r.end ? node::EndName(*r.end) : "") + "," +
           CsvField(r.verdict ? world::RunVerdictName(*r.verdict) : "") + "," + std::to_string(r.steps) + "," +
           StepOrEmpty(r.goal.completion_step, "") + "," +
           (r.min_distance_m ? Fixed(*r.min_distance_m, 4) : std::string()) + "," +
           std::to_string(r.violations.boundary_errors) + "," + std::to_string(r.violations.collision_errors) + "," +
           std::to_string(r.violations.actuator_errors) + "," + std::to_string(r.violations.obstacle_collisions) + "," +
           (r.has_summary ? (r.goal.met ? "true" : "false") : "") + "," + CsvField(r.goal.detail) + "," +
           Fixed(r.wall_time_s, 2) + "," + CsvField(r.problem) + "\n";
  }
  return csv;
}

std::string SweepTable::SummaryMarkdown(const std::vector<std::pair<std::string, std::string>>& facts) const {
  const SweepSummary s = Summary();
  std::string md = "| | |\n|---|---|\n";
  for (const auto& [name, value] : facts) md += "| " + MarkdownCell(name) + " | " + MarkdownCell(value) + " |\n";
  md += "| runs | " + std::to_string(s.listed) + " of " + std::to_string(s.planned) +
        " planned: " + std::to_string(s.ran) + " ran, " + std::to_string(s.failed) + " failed to run, " +
        std::to_string(s.interrupted) + " interrupted" +
        (s.not_run > 0 ? ", " + std::to_string(s.not_run) + " not run" : std::string()) + " |\n";
  if (s.ran > 0 && s.without_goal == s.ran) {
    md += "| success rate | no goal declared (the experiment judges no goal; see its violations) |\n";
  } else {
    md += "| success rate | " + std::to_string(s.succeeded) + " of " + std::to_string(s.ran + s.failed) + " (" +
          Fixed(100.0 * s.success_rate, 1) + " %)" +
          (s.without_goal > 0 ? ", " + std::to_string(s.without_goal) + " runs with no goal declared" : "") + " |\n";
  }
  md += "| completion step | " +
        (s.completed > 0
             ? "mean " + Fixed(s.completion_mean, 0) + ", min " + std::to_string(s.completion_min) + ", max " +
                   std::to_string(s.completion_max) + " (" + std::to_string(s.completed) + " runs completed)"
             : std::string("no run completed")) +
        " |\n";
  md += "| worst min distance | " +
        (s.has_min_distance ? Fixed(s.worst_min_distance_m, 4) + " m (" + s.worst_min_distance_run + ")"
                            : std::string("-")) +
        " |\n";
  md += "| violations, all runs | boundary " + std::to_string(s.violations.boundary_errors) + ", collision " +
        std::to_string(s.violations.collision_errors) + ", actuator " + std::to_string(s.violations.actuator_errors) +
        ", obstacle " + std::to_string(s.violations.obstacle_collisions) + " |\n";
  return md;
}

std::string SweepTable::Markdown(const std::string& title,
                                 const std::vector<std::pair<std::string, std::string>>& facts) const {
  std::string md = "# " + MarkdownCell(title) + "\n\n" + SummaryMarkdown(facts) + "\n";
  const std::string by_value = ByValueMarkdown(results_.size() + 1);
  if (!by_value.empty()) md += by_value + "\n## Runs\n\n";
  md += "| run | seed |";
  for (const std::string& key : keys_) md += " " + MarkdownCell(key) + " |";
  md += " outcome | steps | completion step | min distance (m) | boundary | collision | actuator | obstacle | goal |\n";
  md += "|---|---|";
  for (size_t i = 0; i < keys_.size(); ++i) md += "---|";
  md += "---|---|---|---|---|---|---|---|---|\n";
  for (const SweepRunResult& r : results_) {
    md += "| " + MarkdownCell(r.run.name) + " | " + std::to_string(r.run.seed) + " |";
    for (const auto& parameter : r.run.parameters) md += " " + MarkdownCell(parameter.second) + " |";
    md += " " + MarkdownCell(r.ShortOutcomeText()) + " | " + std::to_string(r.steps) + " | " +
          StepOrEmpty(r.goal.completion_step, "-") + " | " + (r.min_distance_m ? Fixed(*r.min_distance_m, 4) : "-") +
          " | " + std::to_string(r.violations.boundary_errors) + " | " + std::to_string(r.violations.collision_errors) +
          " | " + std::to_string(r.violations.actuator_errors) + " | " +
          std::to_string(r.violations.obstacle_collisions) + " | " + MarkdownCell(r.has_summary ? r.goal.detail : "-") +
          " |\n";
  }
  return md;
}

std::string SweepTable::ByValueMarkdown(size_t max_rows) const {
  return SweepValueStats(keys_, results_).Markdown(max_rows);
}

}  // namespace dream::workflows
