#include "dream/session/run_reporter.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "dream/bridge/metrics_json.h"
#include "dream/bridge/pre_validation.h"
#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/files/json_text.h"
#include "dream/node/run_judge.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/node/run_summary.h"
#include "dream/render/run_geometry.h"
#include "dream/render/trajectory_picture.h"
#include "dream/run_log/run_log.h"
#include "dream/session/experiment_goal.h"
#include "dream/session/realism_notice.h"
#include "dream/session/render_overlays.h"
#include "dream/session/sim_only_notice.h"

namespace dream::session {

/// The run's log, read back once after the run for the metrics, the
/// verifier's counts, the violations located and the picture; when it cannot
/// be read, each of them fails with the reader's error, as when each read it.
struct RunReporter::LogReadBack {
  LogReadBack(const std::string& log_path, const world::WorldParams& world) : path(log_path) {
    try {
      log.emplace(run_log::RunLog::Read(path));
    } catch (const std::exception& e) {
      error = e.what();
      return;
    }
    try {
      located = render::LocateViolations(*log, world, kMaxViolationsListed);
    } catch (const std::exception& e) {
      located_error = e.what();
    }
  }
  /// @throws std::runtime_error (the reader's) when the log could not be read.
  const run_log::RunLog& Get() const {
    if (!log) throw std::runtime_error(error);
    return *log;
  }

  std::string path;
  std::optional<run_log::RunLog> log;
  world::LocatedViolations located;  // by the world's checks on the log's poses
  std::string located_error;         // why they could not be located
  std::string error;
};

RunReporter::RunReporter(const run_config::RunConfig& config, const agent_host::ControllerFactory* factory,
                         std::string factory_error, Options options)
    : config_(config), factory_(factory), factory_error_(std::move(factory_error)), options_(options) {}

nlohmann::ordered_json RunReporter::Metrics(const LogReadBack& log) const {
  nlohmann::ordered_json json;
  if (factory_ == nullptr) {
    spdlog::warn("{}: {}", config_.source, factory_error_);
    json["error"] = factory_error_;
    return json;
  }
  if (!log.log) {
    json["error"] = log.error;
    return json;
  }
  return bridge::MetricsJson(config_, *factory_, *log.log, options_.python_runtime_dir);
}

world::RunJudgement RunReporter::Judge(const Ended& ended, const LogReadBack& log, node::RunSummary* summary) const {
  const node::RunOutcome& outcome = ended.outcome;
  std::optional<world::RunJudgement> judgement = ended.judgement;
  if (!judgement) {
    // The lab's verifier counts each robot outside the arena, the world each
    // step with any: re-count on the log, only when there is something to count.
    int64_t outside = 0;
    if (ended.world->violations().boundary_errors > 0) {
      try {
        outside = bridge::VerifierCounts(log.Get(), config_.world).robots_outside_boundaries;
      } catch (const std::exception& e) {
        spdlog::warn("{}: cannot re-count robots outside the arena ({}); using the steps with any", log.path, e.what());
        outside = -1;
      }
    }
    judgement.emplace(node::JudgeRun(config_, outcome, *ended.world, outside));
  }
  const ExperimentGoal goal = ExperimentGoal::Judge(*summary);
  nlohmann::ordered_json goal_json = goal.Json();
  // A run stopped by --steps at its limit was cut short on purpose: its goal is
  // not judged. A goal that could not be judged at all is a failure either way.
  const bool cut_short = options_.steps_from_command_line && !goal.met && goal.judge_error.empty() &&
                         outcome.steps >= config_.sim.max_steps;
  goal_json["judged"] = !cut_short && goal.has_criterion;
  summary->goal = goal_json;
  if (!cut_short) {
    if (const std::optional<world::VerdictReason> reason = goal.Reason()) judgement->Add(*reason);
  }
  return *judgement;
}

RunResult RunReporter::Report(const Ended& ended) const {
  if (ended.world == nullptr) throw std::logic_error("RunReporter::Report: no world");
  const std::string log_path = ended.dir + "/" + kLogName;
  const node::RunOutcome& outcome = ended.outcome;
  RunResult result;
  result.outcome = outcome;
  // Written whatever the outcome: after a failed run it says why, and the
  // log keeps every whole event up to the failure.
  const LogReadBack log(log_path, config_.world);  // once, for the metrics, the verifier's counts and the picture
  const nlohmann::ordered_json metrics = Metrics(log);
  if (metrics.contains("error")) {
    // The run and its log stand; only the experiment's own numbers are missing.
    spdlog::warn("{}: no experiment metrics: {}", log_path, metrics["error"].get<std::string>());
  }
  // The goal is judged on the summary (robots done, steps) with its metrics.
  // Built once: its verdict fields are set again once the goal is judged.
  node::RunSummary summary =
      node::RunSummary::Of(config_, outcome, *ended.world, kLogName, world::RunJudgement(world::RunReport{}));
  summary.metrics = metrics;
  const std::string& located_error = log.log ? log.located_error : log.error;
  summary.violations_located = located_error.empty() ? node::ViolationsLocatedJson(log.located, kMaxViolationsListed)
                                                     : nlohmann::ordered_json{{"error", located_error}};
  result.judgement = Judge(ended, log, &summary);
  summary.SetVerdict(result.judgement);
  const nlohmann::ordered_json goal = summary.goal;
  result.goal = goal;
  for (auto it = ended.fields.begin(); it != ended.fields.end(); ++it) summary.Set(it.key(), it.value());
  try {
    files::WriteFileAtomically(ended.dir + "/" + kSummaryName, summary.Text());
    result.summary_written = true;
  } catch (const std::exception& e) {
    // A full disk: say so once, and that the run's outputs are incomplete.
    spdlog::error("{} ({} after {} steps; the run's outputs are incomplete)", e.what(), node::EndName(outcome.end),
                  outcome.steps);
    return result;
  }
  PrintVerdict(ended, result.judgement, goal);
  if (outcome.steps > 0 || outcome.end == node::RunOutcome::End::kFinished) {
    const std::string picture_path = ended.dir + "/" + kPictureName;
    result.picture_failed = !DrawPicture(log, picture_path, result.judgement.verdict(), metrics);
    if (!result.picture_failed && !QuietAbout(result.judgement, goal)) {
      *options_.report << "picture: " << picture_path << "\n";
    }
  }
  return result;
}

namespace {

// A goal --steps stopped the run before it was judged: clean, but not a success.
bool GoalNotJudged(const nlohmann::ordered_json& goal) {
  return goal.contains("judged") && goal["judged"] == false && goal["has_criterion"] == true;
}

}  // namespace

bool RunReporter::QuietAbout(const world::RunJudgement& judgement, const nlohmann::ordered_json& goal) const {
  return options_.quiet && judgement.verdict() == world::RunVerdict::kClean && !GoalNotJudged(goal);
}

void RunReporter::PrintVerdict(const Ended& ended, const world::RunJudgement& judgement,
                               const nlohmann::ordered_json& goal) const {
  const node::RunOutcome& outcome = ended.outcome;
  std::ostream& report = *options_.report;
  spdlog::info("{} after {} steps ({:.1f} s simulated, {:.2f} s wall): {}", node::EndName(outcome.end), outcome.steps,
               ended.world->time_s(), outcome.wall_time_s, outcome.reason);
  if (QuietAbout(judgement, goal)) return;
  report << judgement.Text();
  // debug()'s "took approximately 99.00 real seconds" is the time on the lab's
  // robots (its wording, kept word for word); this says what it took here.
  report << fmt::format("(real seconds on the lab: {} steps of {} s; this run took {:.2f} s here)\n", outcome.steps,
                        robotarium::RobotariumConstants::kTimeStepSeconds, outcome.wall_time_s);
  if (const std::string realism = RealismNotice(config_); !realism.empty()) report << realism << "\n";
  if (const std::string sim_only = SimOnlyNotice(config_); !sim_only.empty()) report << sim_only << "\n";
  if (GoalNotJudged(goal)) {
    report << "goal: not judged, --steps " << config_.sim.max_steps << " stopped the run first ("
           << goal["detail"].get<std::string>() << ")\n";
  }
  if (judgement.verdict() == world::RunVerdict::kNotReady || judgement.reasons().size() > 1) {
    report << "verdict: " << world::RunVerdictName(judgement.verdict()) << " (summary.json verdict_reasons";
    report << (judgement.verdict() >= world::RunVerdict::kNotReady ? "; dream export refuses it" : "") << ")\n";
  }
  report << "log:     " << ended.dir + "/" + kLogName << "\nsummary: " << ended.dir + "/" + kSummaryName << "\n";
}

bool RunReporter::DrawPicture(const LogReadBack& log, const std::string& picture_path, world::RunVerdict verdict,
                              const nlohmann::ordered_json& metrics) const {
  try {
    // With the config's goals, like `dream render` draws them.
    render::ArenaOverlays overlays =
        factory_ ? ArenaOverlaysFromConfig(config_, *factory_) : ArenaOverlaysFromConfig(config_);
    AddDeclaredGoals(metrics, &overlays);  // a Python controller's goal_points()
    overlays.run_name = config_.name;
    overlays.verdict = world::RunVerdictName(verdict);  // as summary.json says
    overlays.sim_only = config_.sim_only;
    overlays.violations = log.located;  // as summary.json lists them
    render::TrajectoryPicture::Render(log.Get(), overlays, picture_path, render::RenderFormat::kPng, 1280);
    return true;
  } catch (const std::exception& e) {
    spdlog::error("no {}: {}", kPictureName, e.what());
    return false;
  }
}

world::RunVerdict RunReporter::AddReasons(const std::string& dir, const std::string& section_key,
                                          const nlohmann::ordered_json& section,
                                          const std::vector<world::VerdictReason>& reasons) const {
  const std::string summary_path = dir + "/" + kSummaryName;
  node::RunSummary summary = node::RunSummary::Read(summary_path);
  if (!summary.Has("verdict") || !summary.Has("verdict_reasons")) {
    throw std::runtime_error(summary_path +
                             ": has no verdict (clean, warning, not_ready or rejected) with "
                             "verdict_reasons; is it a dream run's summary?");
  }
  const world::RunVerdict old_verdict = summary.verdict;
  world::RunVerdict verdict = old_verdict;
  for (const world::VerdictReason& reason : reasons) {
    summary.verdict_reasons.push_back(reason);
    verdict = std::max(verdict, reason.verdict);
  }
  summary.verdict = verdict;
  summary.Set(section_key, section);
  files::WriteFileAtomically(summary_path, summary.Text());
  if (verdict != old_verdict && std::filesystem::exists(dir + "/" + kPictureName)) {
    const nlohmann::ordered_json metrics = summary.metrics;
    DrawPicture(LogReadBack(dir + "/" + kLogName, config_.world), dir + "/" + kPictureName, verdict,
                metrics);  // says what summary.json says
  }
  return verdict;
}

}  // namespace dream::session
