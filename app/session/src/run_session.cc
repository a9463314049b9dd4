#include "dream/session/run_session.h"

#include <spdlog/spdlog.h>

#include <optional>
#include <stdexcept>
#include <utility>

#include "dream/bridge/controller_module_copy.h"
#include "dream/bridge/metrics_json.h"
#include "dream/bridge/pre_validation.h"
#include "dream/run_config/world_of_config.h"
#include "dream/files/atomic_file.h"
#include "dream/files/json_text.h"
#include "dream/files/output_folder.h"
#include "dream/node/run_judge.h"
#include "dream/node/refused_record.h"
#include "dream/node/run_summary.h"
#include "dream/node/sim_node.h"
#include "dream/node/true_pose_recording.h"
#include "dream/run_log/run_log.h"
#include "dream/render/trajectory_picture.h"
#include "dream/session/experiment_goal.h"
#include "dream/session/render_overlays.h"
#include "dream/session/terminal_progress.h"
#include "dream/world/realistic_world.h"

namespace dream::session {
namespace {

constexpr const char* kLogName = "run.lcmlog";
constexpr const char* kRefusedLogName = "refused.lcmlog";

}  // namespace

// What the loop left for the report: the world (asked for its counts and
// final poses), how the run ended and what the world adds to summary.json.
struct RunSession::Stepped {
  std::unique_ptr<world::World> world;
  node::RunOutcome outcome;
  nlohmann::ordered_json world_fields = nlohmann::ordered_json::object();
  /// The run's folder was removed and made again while it ran (the log's
  /// .part there is another file): the folder is another run's now.
  bool folder_replaced = false;
};

RunSession::RunSession(run_config::RunConfig config, Options options)
    : config_(std::move(config)), options_(options) {
  try {
    factory_ = std::make_unique<agent_host::ControllerFactory>(config_);
  } catch (const std::exception& e) {
    factory_error_ = e.what();
  }
}

RunSession::RunSession(run_config::RunConfig config) : RunSession(std::move(config), Options()) {}

RunSession::~RunSession() = default;

RunResult RunSession::Run(lcm::LcmInterface& lcm, const Folder& folder) {
  // world.realism: the official world seen and driven as on the lab; off
  // (ideal), the official world itself, with nothing in between.
  GivenWorld own;
  own.make = [this](node::RunRecorder&) { return run_config::WorldOfConfig(config_); };
  return Run(lcm, folder, own);
}

RunResult RunSession::Run(lcm::LcmInterface& lcm, const Folder& folder, const GivenWorld& world) {
  if (ran_) throw std::logic_error("RunSession::Run: a session runs once (" + config_.name + ")");
  ran_ = true;
  const Stepped stepped = Step(lcm, folder, world);
  return Report(stepped, folder.dir);
}

RunSession::Stepped RunSession::Step(lcm::LcmInterface& lcm, const Folder& folder, const GivenWorld& given) {
  // A copy of the config beside the log, so the run folder alone is enough
  // for `dream export` and `dream compare`, and to rerun it.
  files::WriteFileAtomically(folder.dir + "/config.yaml", folder.config_text);
  bridge::KeepControllerModule(config_, files::OutputFolder(folder.dir));
  bridge::KeepRealismFile(config_, files::OutputFolder(folder.dir));
  Stepped stepped;
  const std::string log_path = folder.dir + "/" + kLogName;
  {
    node::RunRecorder recorder(log_path);
    stepped.world = given.make(recorder);
    if (stepped.world == nullptr) throw std::logic_error("RunSession: the given world's make() returned none");
    // A realistic world's log keeps the truth on DREAM_POSES, the agents' view on DREAM_MEASURED_POSES.
    std::optional<node::TruePoseRecording> truth;
    if (const auto* realistic = dynamic_cast<const world::RealisticWorld*>(stepped.world.get())) {
      truth.emplace(recorder, *realistic);
    }
    // What the world refuses is kept apart from the run's log (at most a few MB).
    node::RefusedRecord refused(folder.dir + "/" + kRefusedLogName);
    node::SimNode node(lcm, *stepped.world, &recorder, config_.sim);
    node.set_refused_record(&refused);
    if (given.start_line.empty()) {
      spdlog::info("{}: {} robots, up to {} steps, {} on {}", config_.name, config_.num_robots, config_.sim.max_steps,
                   config::WorldModeName(config_.sim.mode), lcm.url());
    } else {
      spdlog::info("{}", given.start_line);
    }
    TerminalProgress progress(config_.sim.progress_interval_s);
    node.set_progress_reporter(progress.reporter());
    static const std::atomic<bool> never(false);
    stepped.outcome = node.Run(options_.stop != nullptr ? *options_.stop : never);
    try {
      recorder.Close();
    } catch (const std::exception& e) {
      // The node has flushed the log already, so this is rare (a rename that
      // fails); the summary still tells what the run did and why the log is short.
      stepped.outcome.end = node::RunOutcome::End::kFailed;
      stepped.outcome.reason = e.what();
    }
    stepped.outcome.log_events = recorder.events_written();
    stepped.folder_replaced = recorder.part_replaced();
  }
  if (given.summary_fields) stepped.world_fields = given.summary_fields(*stepped.world);
  return stepped;
}

/// The run's log, read back once after the run for the metrics, the
/// verifier's counts and the picture; when it cannot be read, each of them
/// fails with the reader's error, as when each read it.
struct RunSession::LogReadBack {
  explicit LogReadBack(const std::string& log_path) : path(log_path) {
    try {
      log.emplace(run_log::RunLog::Read(path));
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  /// @throws std::runtime_error (the reader's) when the log could not be read.
  const run_log::RunLog& Get() const {
    if (!log) throw std::runtime_error(error);
    return *log;
  }

  std::string path;
  std::optional<run_log::RunLog> log;
  std::string error;
};

nlohmann::ordered_json RunSession::Metrics(const LogReadBack& log) const {
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
  return bridge::MetricsJson(*factory_, *log.log);
}

world::RunJudgement RunSession::Judge(const node::RunOutcome& outcome, const world::World& world, const LogReadBack& log,
                                    nlohmann::ordered_json* summary) const {
  // The lab's verifier counts each robot outside the arena, the world each
  // step with any: re-count on the log, only when there is something to count.
  int64_t outside = 0;
  if (world.violations().boundary_errors > 0) {
    try {
      outside = bridge::VerifierCounts(log.Get(), config_.world).robots_outside_boundaries;
    } catch (const std::exception& e) {
      spdlog::warn("{}: cannot re-count robots outside the arena ({}); using the steps with any", log.path, e.what());
      outside = -1;
    }
  }
  world::RunJudgement judgement = node::JudgeRun(config_, outcome, world, outside);
  const ExperimentGoal goal = ExperimentGoal::Judge(*summary);
  nlohmann::ordered_json goal_json = goal.Json();
  // A run stopped by --steps at its limit was cut short on purpose: its goal is not judged.
  const bool cut_short =
      options_.steps_from_command_line && !goal.met && outcome.steps >= config_.sim.max_steps;
  goal_json["judged"] = !cut_short && goal.has_criterion;
  (*summary)["goal"] = goal_json;
  if (!cut_short) {
    if (const std::optional<world::VerdictReason> reason = goal.Reason()) judgement.Add(*reason);
  }
  return judgement;
}

RunResult RunSession::Report(const Stepped& stepped, const std::string& dir) {
  const std::string log_path = dir + "/" + kLogName;
  const node::RunOutcome& outcome = stepped.outcome;
  const world::World& world = *stepped.world;
  std::ostream& report = *options_.report;
  RunResult result;
  result.outcome = outcome;
  if (stepped.folder_replaced) {
    // Its log, summary and picture there would be another run's, or pass for
    // them: nothing of this run is written over them.
    spdlog::error("{}: {}; no summary.json or picture written there either", dir, outcome.reason);
    report << "failed after " << outcome.steps << " steps: " << outcome.reason << "\n";
    return result;
  }
  // Written whatever the outcome: after a failed run it says why, and the
  // log keeps every whole event up to the failure.
  const LogReadBack log(log_path);  // once, for the metrics, the verifier's counts and the picture
  const nlohmann::ordered_json metrics = Metrics(log);
  if (metrics.contains("error")) {
    // The run and its log stand; only the experiment's own numbers are missing.
    spdlog::warn("{}: no experiment metrics: {}", log_path, metrics["error"].get<std::string>());
  }
  // The goal is judged on the summary (robots done, steps) with its metrics.
  // Built once: its verdict fields are set again once the goal is judged.
  nlohmann::ordered_json summary =
      node::RunSummary(config_, outcome, world, kLogName, node::JudgeRun(config_, outcome, world));
  summary["metrics"] = metrics;
  result.judgement = Judge(outcome, world, log, &summary);
  node::SetSummaryVerdict(&summary, result.judgement);
  const nlohmann::ordered_json goal = summary["goal"];  // a copy: adding world fields may move the summary's entries
  for (auto it = stepped.world_fields.begin(); it != stepped.world_fields.end(); ++it) summary[it.key()] = it.value();
  try {
    files::WriteFileAtomically(dir + "/summary.json", files::JsonText(summary) + "\n");
    result.summary_written = true;
  } catch (const std::exception& e) {
    // A full disk: say so once, and that the run's outputs are incomplete.
    spdlog::error("{} ({} after {} steps; the run's outputs are incomplete)", e.what(), node::EndName(outcome.end),
                  outcome.steps);
    return result;
  }

  const world::RunJudgement& judgement = result.judgement;
  spdlog::info("{} after {} steps ({:.1f} s simulated, {:.2f} s wall): {}", node::EndName(outcome.end), outcome.steps,
               world.time_s(), outcome.wall_time_s, outcome.reason);
  report << judgement.Text();
  if (goal.contains("judged") && goal["judged"] == false && goal["has_criterion"] == true) {
    report << "goal: not judged, --steps " << config_.sim.max_steps << " stopped the run first ("
           << goal["detail"].get<std::string>() << ")\n";
  }
  if (judgement.verdict() == world::RunVerdict::kNotReady || judgement.reasons().size() > 1) {
    report << "verdict: " << world::RunVerdictName(judgement.verdict()) << " (summary.json verdict_reasons";
    report << (judgement.verdict() >= world::RunVerdict::kNotReady ? "; dream export refuses it" : "") << ")\n";
  }
  report << "log:     " << log_path << "\nsummary: " << dir + "/summary.json" << "\n";
  if (outcome.steps > 0 || outcome.end == node::RunOutcome::End::kFinished) {
    const std::string picture_path = dir + "/trajectories.png";
    result.picture_failed = !DrawPicture(log, picture_path, judgement.verdict());
    if (!result.picture_failed) report << "picture: " << picture_path << "\n";
  }
  return result;
}

bool RunSession::DrawPicture(const LogReadBack& log, const std::string& picture_path,
                             world::RunVerdict verdict) const {
  try {
    // With the config's goals, like `dream render` draws them.
    render::ArenaOverlays overlays = factory_ ? ArenaOverlaysFromConfig(config_, *factory_) : ArenaOverlaysFromConfig(config_);
    overlays.run_name = config_.name;
    overlays.verdict = world::RunVerdictName(verdict);  // as summary.json says
    render::TrajectoryPicture::Render(log.Get(), overlays, picture_path, render::RenderFormat::kPng, 1280);
    return true;
  } catch (const std::exception& e) {
    spdlog::error("no trajectories.png: {}", e.what());
    return false;
  }
}

}  // namespace dream::session
