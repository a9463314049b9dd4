#include "hosted_agents.h"
#include "run_output.h"

#include <spdlog/spdlog.h>

#include <nlohmann/json.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "dream/agent_host/controller_factory.h"
#include "dream/bridge/controller_module_copy.h"
#include "dream/bridge/metrics_json.h"
#include "dream/bridge/pre_validation.h"
#include "dream/bridge/run_track.h"
#include "dream/config/config_error.h"
#include "dream/node/atomic_file.h"
#include "dream/node/file_text.h"
#include "dream/node/output_folder.h"
#include "dream/world/realistic_world.h"
#include "dream/node/run_recorder.h"
#include "dream/node/run_judge.h"
#include "dream/world/run_report.h"
#include "dream/node/run_summary.h"
#include "dream/node/sim_node.h"
#include "dream/render/run_track.h"
#include "dream/render/trajectory_picture.h"
#include "dream/node/true_pose_recording.h"
#include "dream/world/unicycle_world.h"
#include "experiment_goal.h"
#include "overridden_config.h"
#include "render_overlays.h"
#include "run_folder_choice.h"
#include "terminal_progress.h"

namespace dream::cli {
namespace {

// The models a run with world.realism had (summary.json "realism").
nlohmann::ordered_json RealismJson(const sim::RealismParams& realism) {
  nlohmann::ordered_json json;
  json["pose_noise_m"] = realism.pose_noise_m;
  json["pose_noise_rad"] = realism.pose_noise_rad;
  json["pose_quantum_m"] = realism.pose_quantum_m;
  json["pose_quantum_rad"] = realism.pose_quantum_rad;
  json["pose_delay_steps"] = realism.pose_delay_steps;
  json["tracking_dropout_probability"] = realism.tracking_dropout_probability;
  json["command_latency_steps"] = realism.command_latency_steps;
  json["command_brake_s"] = realism.command_brake_s;
  json["dead_zone_v_mps"] = realism.dead_zone_v_mps;
  json["dead_zone_w_radps"] = realism.dead_zone_w_radps;
  json["wheel_accel_limit_radps2"] = realism.wheel_accel_limit_radps2;
  json["axle_length_m"] = realism.axle_length_m;
  json["poses_channel_seen_by_agents"] = sim::TruePoseRecording::kMeasuredPosesChannel;
  return json;
}

}  // namespace

config::RunConfig LoadConfig(const RunArgs& args) {
  const OverriddenConfig overridden(args.config_path, args.seed, args.sets);
  config::RunConfig config = overridden.Load();
  if (args.steps != 0) {
    if (args.steps < 1) throw std::invalid_argument("--steps must be >= 1, got " + std::to_string(args.steps));
    config.sim.max_steps = args.steps;
  }
  if (!args.mode.empty()) config.sim.mode = sim::ParseWorldMode(args.mode);
  if (args.all_steps) config.sim.stop_when_done = false;
  // Check the controller section now, so a mistake in it stops every command
  // (sim, launch) before anything starts or any folder is made.
  try {
    HostedAgents::Check(config);
  } catch (const config::ConfigError& e) {
    throw config::ConfigError(overridden.Noted(e.what()));
  }
  return config;
}

std::string ConfigTextForRunFolder(const RunArgs& args, const config::RunConfig& config) {
  return OverriddenConfig(args.config_path, args.seed, args.sets).FolderText(config);
}

std::string PrepareOutputDir(const RunArgs& args, const config::RunConfig& config) {
  return RunFolderChoice(args.out_dir, "runs/" + config.name, args.overwrite).dir();
}

int RunWorld(lcm::LcmInterface& lcm, const config::RunConfig& config, const std::string& config_text,
             const std::string& out_dir, bool steps_from_command_line) {
  // A copy of the config beside the log, so the run folder alone is enough for
  // `dream export` and `dream compare`, and to rerun it.
  sim::WriteFileAtomically(out_dir + "/config.yaml", config_text);
  bridge::KeepControllerModule(config, sim::OutputFolder(out_dir));
  // world.realism: the official world seen and driven as on the lab; off (ideal),
  // the official world itself, with nothing in between.
  std::unique_ptr<sim::World> world_owner;
  const sim::RealisticWorld* realistic = nullptr;
  if (config.realism.IsIdeal()) {
    world_owner = std::make_unique<sim::UnicycleWorld>(config.world, config.initial_poses, config.obstacles);
  } else {
    auto lab_like = std::make_unique<sim::RealisticWorld>(config.world, config.realism, config.seed,
                                                          config.initial_poses, config.obstacles);
    realistic = lab_like.get();
    world_owner = std::move(lab_like);
  }
  sim::World& world = *world_owner;
  const std::string log_path = out_dir + "/run.lcmlog";
  sim::RunOutcome outcome;
  {
    sim::RunRecorder recorder(log_path);
    // The log keeps the truth on DREAM_POSES, the agents' view on DREAM_MEASURED_POSES.
    std::optional<sim::TruePoseRecording> truth;
    if (realistic != nullptr) truth.emplace(recorder, *realistic);
    sim::SimNode node(lcm, world, &recorder, config.sim);
    spdlog::info("{}: {} robots, up to {} steps, {} on {}", config.name, config.num_robots, config.sim.max_steps,
                 sim::WorldModeName(config.sim.mode), lcm.url());
    TerminalProgress progress(config.sim.progress_interval_s);
    node.set_progress_reporter(progress.reporter());
    outcome = node.Run(StopFlag());
    try {
      recorder.Close();
    } catch (const std::exception& e) {
      // The node has flushed the log already, so this is rare (a rename that
      // fails); the summary still tells what the run did and why the log is short.
      outcome.end = sim::RunOutcome::End::kFailed;
      outcome.reason = e.what();
    }
    outcome.log_events = recorder.events_written();
  }
  // What the world adds to summary.json.
  nlohmann::ordered_json world_fields = nlohmann::ordered_json::object();
  if (realistic != nullptr) {
    world_fields["realism"] = RealismJson(config.realism);
    // Where the robots really ended (world.poses() is what the agents were sent last).
    nlohmann::ordered_json poses = nlohmann::ordered_json::array();
    for (const sim::Pose2& pose : realistic->true_poses()) poses.push_back({pose.x_m, pose.y_m, pose.theta_rad});
    world_fields["final_poses"] = poses;
  }
  return ReportRun(config, outcome, world, out_dir, steps_from_command_line, world_fields);
}

sim::RunJudgement JudgeRunAndGoal(const config::RunConfig& config, const sim::RunOutcome& outcome,
                                  const sim::World& world, const std::string& log_path, nlohmann::ordered_json* summary,
                                  bool steps_from_command_line) {
  // The lab's verifier counts each robot outside the arena, the world each
  // step with any: re-count on the log, only when there is something to count.
  int64_t outside = 0;
  if (world.violations().boundary_errors > 0) {
    try {
      outside = bridge::VerifierCounts(bridge::ReadRunTrack(log_path), config.world).robots_outside_boundaries;
    } catch (const std::exception& e) {
      spdlog::warn("{}: cannot re-count robots outside the arena ({}); using the steps with any", log_path, e.what());
      outside = -1;
    }
  }
  sim::RunJudgement judgement = sim::JudgeRun(config, outcome, world, outside);
  const ExperimentGoal goal = ExperimentGoal::Judge(*summary);
  nlohmann::ordered_json goal_json = goal.Json();
  // A run stopped by --steps at its limit was cut short on purpose: its goal is not judged.
  const bool cut_short = steps_from_command_line && !goal.met && outcome.steps >= config.sim.max_steps;
  goal_json["judged"] = !cut_short && goal.has_criterion;
  (*summary)["goal"] = goal_json;
  if (!cut_short) {
    if (const std::optional<sim::VerdictReason> reason = goal.Reason()) judgement.Add(*reason);
  }
  return judgement;
}

int ReportRun(const config::RunConfig& config, const sim::RunOutcome& outcome, const sim::World& world,
              const std::string& out_dir, bool steps_from_command_line, const nlohmann::ordered_json& world_fields) {
  const std::string log_path = out_dir + "/run.lcmlog";
  // Written whatever the outcome: after a failed run it says why, and the log
  // keeps every whole event up to the failure.
  // One factory for the metrics and the picture (it loads the config's plugins and reads the section).
  std::optional<agents::ControllerFactory> factory;
  try {
    factory.emplace(config);
  } catch (const std::exception& e) {
    spdlog::warn("{}: {}", config.source, e.what());
  }
  nlohmann::ordered_json metrics =
      factory ? bridge::MetricsJson(*factory, log_path) : bridge::MetricsJson(config, log_path);
  if (metrics.contains("error")) {
    // The run and its log stand; only the experiment's own numbers are missing.
    spdlog::warn("{}: no experiment metrics: {}", log_path, metrics["error"].get<std::string>());
  }
  nlohmann::ordered_json summary =
      nlohmann::ordered_json::parse(sim::RunSummaryJson(config, outcome, world, "run.lcmlog"));
  summary["metrics"] = metrics;
  const sim::RunJudgement judgement =
      JudgeRunAndGoal(config, outcome, world, log_path, &summary, steps_from_command_line);
  const nlohmann::ordered_json goal = summary["goal"];
  summary = nlohmann::ordered_json::parse(sim::RunSummaryJson(config, outcome, world, "run.lcmlog", judgement));
  summary["metrics"] = metrics;
  summary["goal"] = goal;
  for (auto it = world_fields.begin(); it != world_fields.end(); ++it) summary[it.key()] = it.value();
  try {
    sim::WriteFileAtomically(out_dir + "/summary.json", summary.dump(2) + "\n");
  } catch (const std::exception& e) {
    // A full disk: say so once, and that the run's outputs are incomplete.
    spdlog::error("{} ({} after {} steps; the run's outputs are incomplete)", e.what(), sim::EndName(outcome.end),
                  outcome.steps);
    return kExitRunFailed;
  }

  spdlog::info("{} after {} steps ({:.1f} s simulated, {:.2f} s wall): {}", sim::EndName(outcome.end),
               outcome.steps, world.time_s(), outcome.wall_time_s, outcome.reason);
  std::cout << judgement.Text();
  if (goal.contains("judged") && goal["judged"] == false && goal["has_criterion"] == true) {
    std::cout << "goal: not judged, --steps " << config.sim.max_steps << " stopped the run first ("
              << goal["detail"].get<std::string>() << ")\n";
  }
  if (judgement.verdict() == sim::RunVerdict::kNotReady || judgement.reasons().size() > 1) {
    std::cout << "verdict: " << sim::RunVerdictName(judgement.verdict()) << " (summary.json verdict_reasons";
    std::cout << (judgement.verdict() >= sim::RunVerdict::kNotReady ? "; dream export refuses it" : "") << ")\n";
  }
  std::cout << "log:     " << log_path << "\nsummary: " << out_dir << "/summary.json\n";
  bool picture_failed = false;
  if (outcome.steps > 0 || outcome.end == sim::RunOutcome::End::kFinished) {
    try {
      // With the config's goals, like `dream render` draws them.
      sim::ArenaOverlays overlays = factory ? ArenaOverlaysFromConfig(config, *factory) : ArenaOverlaysFromConfig(config);
      overlays.run_name = config.name;
      overlays.verdict = sim::RunVerdictName(judgement.verdict());  // as summary.json says
      sim::TrajectoryPicture::Render(sim::RunTrack::Read(log_path), overlays, out_dir + "/trajectories.png",
                                     sim::RenderFormat::kPng, 1280);
      std::cout << "picture: " << out_dir << "/trajectories.png\n";
    } catch (const std::exception& e) {
      spdlog::error("no trajectories.png: {}", e.what());
      picture_failed = true;
    }
  }
  const int exit_code = ExitCodeFor(outcome, judgement);
  return picture_failed ? kExitRunFailed : exit_code;
}

int ExitCodeFor(const sim::RunOutcome& outcome, const sim::RunJudgement& judgement) {
  const int ended = ExitCodeFor(outcome, judgement.report());
  if (ended != kExitOk && ended != kExitRejected) return ended;  // did not finish, interrupted
  // A robot whose controller failed makes the run fail, whatever the rest did.
  if (!outcome.robot_faults.empty()) return kExitRunFailed;
  switch (judgement.verdict()) {
    case sim::RunVerdict::kRejected:
      return kExitRejected;
    case sim::RunVerdict::kNotReady:
      return kExitNotReady;
    case sim::RunVerdict::kClean:
    case sim::RunVerdict::kWarning:
      break;
  }
  return kExitOk;
}

int ExitCodeFor(const sim::RunOutcome& outcome, const sim::RunReport& report) {
  switch (outcome.end) {
    case sim::RunOutcome::End::kFinished:
      return report.verdict == sim::RunVerdict::kRejected ? kExitRejected : kExitOk;
    case sim::RunOutcome::End::kInterrupted:
      return kExitInterrupted;
    default:
      spdlog::error("{}", outcome.reason);
      return kExitRunFailed;
  }
}

}  // namespace dream::cli
