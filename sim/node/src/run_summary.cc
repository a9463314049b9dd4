#include "dream/node/run_summary.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

#include "dream/lcm/channels.h"
#include "dream/lcm/run_id.h"
#include "dream/files/json_text.h"
#include "dream/node/true_pose_recording.h"
#include "dream/world/barrier_world.h"
#include "dream/world/realistic_world.h"
#include "dream/world/run_report.h"

namespace dream::node {

void SetSummaryVerdict(nlohmann::ordered_json* summary, const world::RunJudgement& judgement) {
  nlohmann::ordered_json& json = *summary;
  json["verdict"] = world::RunVerdictName(judgement.verdict());
  nlohmann::json reasons = nlohmann::json::array();
  for (const world::VerdictReason& reason : judgement.reasons()) {
    reasons.push_back({{"rule", reason.rule},
                       {"verdict", world::RunVerdictName(reason.verdict)},
                       {"problem", reason.problem},
                       {"find_out", reason.find_out}});
  }
  json["verdict_reasons"] = reasons;
  json["robotarium_verdict"] = world::RunVerdictName(judgement.report().verdict);
  json["robotarium_report"] = judgement.report().Text();
}

nlohmann::ordered_json ViolationsLocatedJson(const world::LocatedViolations& located, size_t max_listed) {
  nlohmann::ordered_json listed = nlohmann::ordered_json::array();
  for (const world::LocatedViolation& v : located.listed) {
    nlohmann::ordered_json entry;
    entry["kind"] = world::LocatedViolationKindName(v.kind);
    entry["robots"] = v.kind == world::LocatedViolation::Kind::kCollision ? nlohmann::json::array({v.robot, v.other})
                                                                           : nlohmann::json::array({v.robot});
    if (v.kind == world::LocatedViolation::Kind::kObstacle) entry["obstacle"] = v.other;
    entry["first_step"] = v.first_step;
    entry["last_step"] = v.last_step;
    entry["position"] = {v.x_m, v.y_m};
    // How bad it got: metres outside, the pair's closest centres, or the deepest overlap.
    const char* worst_key = v.kind == world::LocatedViolation::Kind::kBoundary    ? "worst_outside_m"
                            : v.kind == world::LocatedViolation::Kind::kCollision ? "closest_m"
                                                                                  : "worst_overlap_m";
    if (std::isfinite(v.worst_m)) entry[worst_key] = v.worst_m;
    listed.push_back(entry);
  }
  nlohmann::ordered_json json;
  json["listed"] = listed;
  json["unlisted"] = located.unlisted;
  json["max_listed"] = max_listed;
  return json;
}

std::string RunSummaryJson(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                           const std::string& log_file_name, const world::RunJudgement& judgement) {
  return files::JsonText(RunSummary(config, outcome, world, log_file_name, judgement)) + "\n";
}

namespace {

/// What the bus brought that the run did not use: rejected, conflicting, refused and bad messages.
void AddMessageAccounting(const RunOutcome& outcome, nlohmann::ordered_json* json) {
  (*json)["rejected_commands"] = outcome.rejected_commands;
  (*json)["command_conflicts"] = outcome.command_conflicts;
  nlohmann::json other_worlds = nlohmann::json::array();
  for (int64_t id : outcome.other_worlds) other_worlds.push_back(lcm::RunIdText(id));
  (*json)["other_worlds"] = other_worlds;
  (*json)["robots_ever_lost"] = outcome.robots_ever_lost;
  nlohmann::json faults = nlohmann::json::object();
  for (const auto& [id, detail] : outcome.robot_faults) faults[std::to_string(id)] = detail;
  (*json)["robot_faults"] = faults;
  (*json)["robots_done"] = outcome.robots_done;
  (*json)["bad_messages"] = outcome.bad_messages;
  (*json)["bad_message_senders"] = outcome.bad_message_senders;
  nlohmann::json refused = nlohmann::json::object();
  for (const auto& [channel, seen] : outcome.refused) {
    refused[channel] = {{"count", seen.count}, {"first_step", seen.first_step}};
  }
  (*json)["refused_messages"] = refused;
  // Only the file's name: it lies beside the log, as `log` does.
  (*json)["refused_log"] = std::filesystem::path(outcome.refused_log).filename().string();
  (*json)["refused_log_events"] = outcome.refused_log_events;
  (*json)["bad_message_first"] = outcome.bad_message_first;
  (*json)["handler_failures"] = outcome.handler_failures;
  (*json)["dropped_messages"] = outcome.dropped_messages;
}

/// world.realism: its models, and what the tracker model did to the agents' view.
void AddRealism(const run_config::RunConfig& config, const world::RealisticWorld& realistic,
                nlohmann::ordered_json* json) {
  nlohmann::ordered_json realism;
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    if (field.number != nullptr) {
      realism[field.key] = config.realism.*field.number;
    } else {
      realism[field.key] = config.realism.*field.steps;
    }
  }
  if (!config.realism_file.empty()) realism["file"] = config.realism_file;
  realism["poses_channel_seen_by_agents"] = lcm::kMeasuredPosesChannel;
  (*json)["realism"] = realism;
  nlohmann::json lost = nlohmann::json::array();
  for (const world::RealisticWorld::TrackerLoss& loss : realistic.tracker_losses()) {
    lost.push_back({{"robot", loss.robot_id}, {"step", loss.step}});
  }
  nlohmann::json robots = nlohmann::json::array();
  for (const world::RobotTraits& traits : realistic.robot_traits()) {
    robots.push_back({{"linear_gain", traits.linear_gain},
                      {"angular_gain", traits.angular_gain},
                      {"heading_drift_radps", traits.heading_drift_radps}});
  }
  (*json)["realism_stats"] = {{"dropped_measurements", realistic.dropped_measurements()},
                              {"robots_lost_to_tracker", lost},
                              {"late_steps", realistic.late_steps()},
                              {"loop_stalls", realistic.stalls()},
                              {"late_time_s", realistic.late_time_s()},
                              {"robot_traits", robots}};
}

}  // namespace

nlohmann::ordered_json RunSummary(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                                  const std::string& log_file_name, const world::RunJudgement& judgement) {
  nlohmann::ordered_json json;
  json["run"] = config.name;
  json["config"] = config.source;
  json["seed"] = config.seed;
  json["mode"] = config::WorldModeName(config.sim.mode);
  json["robots"] = config.num_robots;
  json["sim_only"] = config.sim_only;  // declared for simulation only: never a lab-ready run
  json["end"] = EndName(outcome.end);
  json["reason"] = outcome.reason;
  json["steps"] = outcome.steps;
  json["max_steps"] = config.sim.max_steps;
  json["simulated_time_s"] = world.time_s();
  json["wall_time_s"] = outcome.wall_time_s;
  json["steps_per_second"] =
      outcome.wall_time_s > 0 ? static_cast<double>(outcome.steps) / outcome.wall_time_s : 0.0;
  const world::ViolationCounts& counts = world.violations();
  json["violations"] = {{"boundary_errors", counts.boundary_errors},
                        {"collision_errors", counts.collision_errors},
                        {"actuator_errors", counts.actuator_errors},
                        {"obstacle_collisions", counts.obstacle_collisions}};
  SetSummaryVerdict(&json, judgement);
  json["run_id"] = lcm::RunIdText(outcome.run_id);
  AddMessageAccounting(outcome, &json);
  json["log"] = log_file_name;
  json["log_events"] = outcome.log_events;
  // Where the robots really ended: a realistic world's poses() are what the
  // agents were sent last (measured), its true_poses() where they are.
  const auto* realistic = dynamic_cast<const world::RealisticWorld*>(&world::SteppingWorldOf(world));
  nlohmann::json poses = nlohmann::json::array();
  for (const world::Pose2& pose : realistic != nullptr ? realistic->true_poses() : world.poses()) {
    poses.push_back({pose.x_m, pose.y_m, pose.theta_rad});
  }
  json["final_poses"] = poses;
  if (realistic != nullptr) AddRealism(config, *realistic, &json);
  return json;
}

}  // namespace dream::node
