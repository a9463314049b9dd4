#include "dream/workflows/view_replay.h"

#include <spdlog/spdlog.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "dream/files/file_text.h"
#include "dream/files/run_log_path.h"
#include "dream/node/run_summary.h"
#include "dream/run_config/run_config.h"
#include "dream/run_log/run_log.h"
#include "dream/session/experiment_goal.h"
#include "dream/view/metric_timeline.h"
#include "dream/view/replay_json.h"
#include "dream/workflows/run_view.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

/// The run's config: `config_path`, else config.yaml beside the log. One that
/// cannot be read or is another run's is an error when given, a warning when
/// found beside the log.
std::optional<run_config::RunConfig> ConfigOfRun(const std::string& config_path, const std::string& log_path,
                                                 int log_robots) {
  std::string path = config_path;
  if (path.empty()) {
    const fs::path beside = fs::path(log_path).parent_path() / "config.yaml";
    if (!fs::is_regular_file(beside)) return std::nullopt;
    path = beside.string();
  }
  try {
    run_config::RunConfig config = run_config::LoadRunConfigFile(path);
    if (log_robots > 0 && config.num_robots != log_robots) {
      throw std::runtime_error(path + " has " + std::to_string(config.num_robots) + " robots, " + log_path + " " +
                               std::to_string(log_robots) + ": not this run's config");
    }
    return config;
  } catch (const std::exception& e) {
    if (!config_path.empty()) throw;
    spdlog::warn("dream view: drawing without the config's goals and radio: {}", e.what());
    return std::nullopt;
  }
}

/// A metric's value as the page lists it; lists and tables (goal points,
/// per-robot series) are left to summary.json.
std::optional<std::string> MetricText(const nlohmann::json& value) {
  constexpr size_t kMaxChars = 80;
  if (value.is_number()) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", value.get<double>());
    return std::string(text);
  }
  if (value.is_boolean()) return std::string(value.get<bool>() ? "true" : "false");
  if (value.is_string()) return value.get<std::string>().substr(0, kMaxChars);
  return std::nullopt;
}

/// summary.json's series ([[step, value], ...]: a Python controller's metrics() per step) not
/// computed here, added whole.
void AddSummarySeries(const std::string& log_path, view::MetricTimeline* timeline) {
  const std::string summary_path = (fs::path(log_path).parent_path() / node::RunSummary::kFileName).string();
  std::error_code error;
  if (!fs::exists(summary_path, error)) return;
  try {
    const node::RunSummary summary = node::RunSummary::Read(summary_path);
    if (!summary.metrics.is_object()) return;
    for (const auto& [name, value] : summary.metrics.items()) {
      if (!value.is_array() || value.empty()) continue;
      std::vector<std::array<double, 2>> points;
      for (const auto& point : value) {
        if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) break;
        points.push_back({point[0].get<double>(), point[1].get<double>()});
      }
      if (points.size() == value.size()) timeline->AddSeries(name, points);
    }
  } catch (const std::exception& e) {
    spdlog::warn("{}: its metric series are not plotted: {}", summary_path, e.what());
  }
}

/// The run's metrics over time: the kind's, computed on every step of the log (the setup's
/// metrics, from the config), then summary.json's other series.
view::MetricTimeline MetricsOfRun(const run_log::RunLog& log, const std::string& log_path,
                                  const view::ViewSetup& setup) {
  view::MetricTimeline timeline;
  if (setup.metrics) {
    try {
      std::unique_ptr<view::StepMetrics> metrics = setup.metrics();
      timeline = view::MetricTimeline::OfRun(log, *metrics);
    } catch (const std::exception& e) {
      spdlog::warn("dream view: the kind's metrics are not plotted: {}", e.what());
      timeline = view::MetricTimeline();
    }
  }
  AddSummarySeries(log_path, &timeline);
  return timeline;
}

}  // namespace

std::optional<view::ViewSetup::Judged> ViewReplay::JudgedOfRun(const std::string& log_path) {
  const std::string summary_path = (fs::path(log_path).parent_path() / node::RunSummary::kFileName).string();
  std::error_code error;
  if (!fs::exists(summary_path, error)) return std::nullopt;
  try {
    const node::RunSummary summary = node::RunSummary::Read(summary_path);
    if (!summary.Has("verdict")) return std::nullopt;
    view::ViewSetup::Judged judged;
    judged.verdict = world::RunVerdictName(summary.verdict);  // the page's text
    for (const world::VerdictReason& reason : summary.verdict_reasons) {
      if (judged.reasons.size() == view::ViewSetup::Judged::kMaxListed) break;
      judged.reasons.push_back(reason.rule + ": " + reason.problem);
    }
    judged.goal = session::ExperimentGoal::Text(summary.goal.is_object() ? nlohmann::json(summary.goal)
                                                                         : nlohmann::json::object());
    const nlohmann::json metrics =
        summary.metrics.is_object() ? nlohmann::json(summary.metrics) : nlohmann::json::object();
    for (const auto& [name, value] : metrics.items()) {
      if (judged.metrics.size() == view::ViewSetup::Judged::kMaxListed) break;
      if (name == "kind") continue;  // the experiment's name, not a measure
      if (std::optional<std::string> text = MetricText(value)) judged.metrics.emplace_back(name, *text);
    }
    return judged;
  } catch (const std::exception& e) {
    spdlog::warn("{}: not read, the page shows the verdict of the counts only: {}", summary_path, e.what());
    return std::nullopt;
  }
}

std::optional<view::ViewSetup::Judged> ViewReplay::JudgedOfVerdict(const run_verdict_t& verdict) {
  static const char* const kNames[] = {"clean", "warning", "not_ready", "rejected"};
  if (verdict.verdict < run_verdict_t::CLEAN || verdict.verdict > run_verdict_t::REJECTED) return std::nullopt;
  view::ViewSetup::Judged judged;
  judged.verdict = kNames[verdict.verdict];
  judged.goal = verdict.goal_text.substr(0, 300);
  std::istringstream lines(verdict.reasons);
  for (std::string line; std::getline(lines, line) && judged.reasons.size() < view::ViewSetup::Judged::kMaxListed;) {
    judged.reasons.push_back(line.substr(0, 300));
  }
  return judged;
}

ViewReplay ViewReplay::OfRun(const std::string& run, const std::string& config_path,
                             const std::string& python_runtime_dir) {
  const std::string log_path = files::RunLogPath(run);
  const run_log::RunLog log = run_log::RunLog::Read(log_path);
  if (log.poses().empty()) {
    throw std::runtime_error(log_path + ": no DREAM_POSES that decode: nothing to replay" +
                             (log.Flaw(true) ? " (" + *log.Flaw(true) + ")" : std::string()));
  }
  ViewReplay replay;
  if (const std::optional<run_config::RunConfig> config = ConfigOfRun(config_path, log_path, log.num_robots())) {
    replay.setup = ViewSetupOfConfig(*config, view::ViewSetup::Mode::kReplay, run, python_runtime_dir,
                                     fs::absolute(log_path).parent_path().string());
  }
  replay.setup.mode = view::ViewSetup::Mode::kReplay;
  replay.setup.source = run;
  replay.setup.judged = JudgedOfRun(log_path);
  // A log alone (no summary.json beside it): the verdict its world appended, if any. A summary
  // that cannot be read is said so and not replaced: the view then shows no verdict of the one judge.
  std::error_code error;
  const bool summary_beside = fs::exists(fs::path(log_path).parent_path() / node::RunSummary::kFileName, error);
  if (!replay.setup.judged && !summary_beside && log.verdict()) replay.setup.judged = JudgedOfVerdict(*log.verdict());
  const view::MetricTimeline metrics = MetricsOfRun(log, log_path, replay.setup);
  replay.run_json = view::RunReplayJson(log, replay.setup, view::kMaxPoseValues, &metrics);
  replay.steps = log.poses().size();
  replay.first_step = log.first_step();
  replay.last_step = log.last_step();
  return replay;
}

}  // namespace dream::workflows
