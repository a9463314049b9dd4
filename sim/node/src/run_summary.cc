#include "dream/node/run_summary.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "dream/files/json_text.h"
#include "dream/files/file_text.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/run_id.h"
#include "dream/node/true_pose_recording.h"
#include "dream/world/barrier_world.h"
#include "dream/world/realistic_world.h"
#include "dream/world/run_report.h"

namespace dream::node {

nlohmann::ordered_json VerdictReasonJson(const world::VerdictReason& reason) {
  return {{"rule", reason.rule},
          {"verdict", world::RunVerdictName(reason.verdict)},
          {"problem", reason.problem},
          {"find_out", reason.find_out}};
}

void SetSummaryVerdict(nlohmann::ordered_json* summary, const world::RunJudgement& judgement) {
  nlohmann::ordered_json& json = *summary;
  json["verdict"] = world::RunVerdictName(judgement.verdict());
  nlohmann::ordered_json reasons = nlohmann::ordered_json::array();
  for (const world::VerdictReason& reason : judgement.reasons()) reasons.push_back(VerdictReasonJson(reason));
  json["verdict_reasons"] = reasons;
  json["robotarium_verdict"] = world::RunVerdictName(judgement.report().verdict);
  json["robotarium_report"] = judgement.report().Text();
}

void RunSummary::SetVerdict(const world::RunJudgement& judgement) {
  verdict = judgement.verdict();
  verdict_reasons = judgement.reasons();
  robotarium_verdict = judgement.report().verdict;
  robotarium_report = judgement.report().Text();
}

const std::vector<std::pair<const char*, RunOutcome::End>>& RunSummary::EndNames() {
  static const std::vector<std::pair<const char*, RunOutcome::End>> names = [] {
    std::vector<std::pair<const char*, RunOutcome::End>> list;
    for (RunOutcome::End end : {RunOutcome::End::kFinished, RunOutcome::End::kInterrupted,
                                RunOutcome::End::kStartTimeout, RunOutcome::End::kFailed}) {
      list.emplace_back(EndName(end), end);
    }
    return list;
  }();
  return names;
}

const std::vector<std::pair<const char*, world::RunVerdict>>& RunSummary::VerdictNames() {
  static const std::vector<std::pair<const char*, world::RunVerdict>> names = [] {
    std::vector<std::pair<const char*, world::RunVerdict>> list;
    for (world::RunVerdict verdict : {world::RunVerdict::kClean, world::RunVerdict::kWarning,
                                      world::RunVerdict::kNotReady, world::RunVerdict::kRejected}) {
      list.emplace_back(world::RunVerdictName(verdict), verdict);
    }
    return list;
  }();
  return names;
}

namespace {

constexpr const char* kCountKeys[] = {"boundary_errors", "collision_errors", "actuator_errors", "obstacle_collisions"};

int64_t* CountOf(world::ViolationCounts& counts, size_t i) {
  int64_t* fields[] = {&counts.boundary_errors, &counts.collision_errors, &counts.actuator_errors,
                       &counts.obstacle_collisions};
  return fields[i];
}

/// Writes each field into summary.json's object, in the list's order.
class JsonWriter {
 public:
  explicit JsonWriter(nlohmann::ordered_json* json) : json_(*json) {}
  void Text(const char* key, const std::string& value) { json_[key] = value; }
  void Whole(const char* key, int64_t value, int64_t) { json_[key] = value; }
  void Unsigned(const char* key, uint64_t value) { json_[key] = value; }
  void Number(const char* key, double value) { json_[key] = value; }
  void Flag(const char* key, bool value) { json_[key] = value; }
  template <typename E>
  void Choice(const char* key, E value, const std::vector<std::pair<const char*, E>>& names, const char*) {
    for (const auto& [name, choice] : names) {
      if (choice == value) json_[key] = name;
    }
  }
  void Counts(const char* key, world::ViolationCounts counts) {
    nlohmann::ordered_json object;
    for (size_t i = 0; i < std::size(kCountKeys); ++i) object[kCountKeys[i]] = *CountOf(counts, i);
    json_[key] = object;
  }
  void Reasons(const char* key, const std::vector<world::VerdictReason>& reasons) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const world::VerdictReason& reason : reasons) list.push_back(VerdictReasonJson(reason));
    json_[key] = list;
  }
  void Section(const char* key, const nlohmann::ordered_json& value, RunSummary::JsonKind) {
    if (!value.is_null()) json_[key] = value;  // null: a section this run has not
  }

 private:
  nlohmann::ordered_json& json_;
};

/// Reads each field the JSON has, checked against the list; keeps the keys it read.
class JsonReader {
 public:
  JsonReader(const nlohmann::ordered_json& json, const std::string& source, std::set<std::string>* read)
      : json_(json), source_(source), read_(*read) {}

  void Text(const char* key, std::string& value) {
    if (const nlohmann::ordered_json* field = Field(key)) {
      if (!field->is_string()) Fail(key, "text", *field);
      value = field->get<std::string>();
    }
  }
  void Whole(const char* key, int64_t& value, int64_t least) {
    if (const nlohmann::ordered_json* field = Field(key)) value = WholeOf(key, *field, least);
  }
  void Unsigned(const char* key, uint64_t& value) {
    if (const nlohmann::ordered_json* field = Field(key)) {
      if (field->is_number_unsigned()) {
        value = field->get<uint64_t>();
      } else {
        value = static_cast<uint64_t>(WholeOf(key, *field, 0));
      }
    }
  }
  void Number(const char* key, double& value) {
    if (const nlohmann::ordered_json* field = Field(key)) {
      if (!field->is_number() || !std::isfinite(field->get<double>())) Fail(key, "a number", *field);
      value = field->get<double>();
    }
  }
  void Flag(const char* key, bool& value) {
    if (const nlohmann::ordered_json* field = Field(key)) {
      if (!field->is_boolean()) Fail(key, "true or false", *field);
      value = field->get<bool>();
    }
  }
  template <typename E>
  void Choice(const char* key, E& value, const std::vector<std::pair<const char*, E>>& names, const char*) {
    const nlohmann::ordered_json* field = Field(key);
    if (field == nullptr) return;
    value = ChoiceOf(key, *field, names);
  }
  void Counts(const char* key, world::ViolationCounts& counts) {
    const nlohmann::ordered_json* field = Field(key);
    if (field == nullptr) return;
    if (!field->is_object()) Fail(key, "an object of counts", *field);
    for (size_t i = 0; i < std::size(kCountKeys); ++i) {
      const auto it = field->find(kCountKeys[i]);
      if (it != field->end()) *CountOf(counts, i) = WholeOf(std::string(key) + "." + kCountKeys[i], *it, 0);
    }
  }
  void Reasons(const char* key, std::vector<world::VerdictReason>& reasons) {
    const nlohmann::ordered_json* field = Field(key);
    if (field == nullptr) return;
    if (!field->is_array()) Fail(key, "a list", *field);
    reasons.clear();
    for (size_t i = 0; i < field->size(); ++i) {
      const nlohmann::ordered_json& entry = (*field)[i];
      const std::string at = std::string(key) + "[" + std::to_string(i) + "]";
      if (!entry.is_object()) Fail(at, "an object with rule, verdict, problem and find_out", entry);
      world::VerdictReason reason;
      auto text = [&](const char* name) {
        const auto it = entry.find(name);
        if (it == entry.end() || !it->is_string()) {
          Fail(at + "." + name, "text", it == entry.end() ? nlohmann::ordered_json() : *it);
        }
        return it->get<std::string>();
      };
      reason.rule = text("rule");
      const nlohmann::ordered_json verdict = entry.contains("verdict") ? entry["verdict"] : nlohmann::ordered_json();
      reason.verdict = ChoiceOf(at + ".verdict", verdict, RunSummary::VerdictNames());
      reason.problem = text("problem");
      reason.find_out = text("find_out");
      reasons.push_back(std::move(reason));
    }
  }
  void Section(const char* key, nlohmann::ordered_json& value, RunSummary::JsonKind kind) {
    const nlohmann::ordered_json* field = Field(key);
    if (field == nullptr) return;
    const bool object = kind == RunSummary::JsonKind::kObject;
    if (object ? !field->is_object() : !field->is_array()) Fail(key, object ? "an object" : "a list", *field);
    value = *field;
  }

 private:
  const nlohmann::ordered_json* Field(const char* key) {
    const auto it = json_.find(key);
    if (it == json_.end()) return nullptr;
    read_.insert(key);
    return &*it;
  }
  int64_t WholeOf(const std::string& key, const nlohmann::ordered_json& field, int64_t least) const {
    const bool whole = field.is_number_integer() &&
                       (!field.is_number_unsigned() ||
                        field.get<uint64_t>() <= static_cast<uint64_t>(std::numeric_limits<int64_t>::max()));
    if (!whole || field.get<int64_t>() < least) {
      Fail(key, "a whole number >= " + std::to_string(least), field);
    }
    return field.get<int64_t>();
  }
  template <typename E>
  E ChoiceOf(const std::string& key, const nlohmann::ordered_json& field,
             const std::vector<std::pair<const char*, E>>& names) const {
    std::string allowed;
    for (const auto& [name, choice] : names) {
      if (field.is_string() && field.get<std::string>() == name) return choice;
      allowed += (allowed.empty() ? "" : ", ") + std::string(name);
    }
    Fail(key, "one of " + allowed, field);
  }
  [[noreturn]] void Fail(const std::string& key, const std::string& expected, const nlohmann::ordered_json& got) const {
    std::string value = got.is_null() ? std::string("nothing") : got.dump();
    if (value.size() > 80) value = value.substr(0, 77) + "...";  // a value may be megabytes: its start names it
    throw std::runtime_error(source_ + ": " + key + ": expected " + expected + ", got " + value);
  }

  const nlohmann::ordered_json& json_;
  const std::string& source_;
  std::set<std::string>& read_;
};

}  // namespace

void RunSummary::ReadInto(const nlohmann::ordered_json& json, const std::string& source) {
  std::set<std::string> read;
  JsonReader reader(json, source, &read);
  ListFields(reader);
  for (auto it = json.begin(); it != json.end(); ++it) {
    if (read.count(it.key()) == 0) sections[it.key()] = it.value();
    present_.insert(it.key());
  }
}

RunSummary RunSummary::FromJson(const nlohmann::ordered_json& json, const std::string& source) {
  if (!json.is_object()) {
    throw std::runtime_error(source + ": not a run's summary: a JSON " + std::string(json.type_name()) +
                             ", not an object");
  }
  RunSummary summary;
  summary.ReadInto(json, source);
  return summary;
}

RunSummary RunSummary::Read(const std::string& path) {
  const std::string text = files::ReadFileText(path, kMaxBytes);
  nlohmann::ordered_json json;  // ordered: the sections others added stay in the file's order
  try {
    json = nlohmann::ordered_json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path + ": not valid JSON: " + e.what());
  }
  return FromJson(json, path);
}

nlohmann::ordered_json RunSummary::Json() const {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  JsonWriter writer(&json);
  // ListFields takes the fields by reference for the reader; the writer only reads them.
  const_cast<RunSummary*>(this)->ListFields(writer);
  for (auto it = sections.begin(); it != sections.end(); ++it) json[it.key()] = it.value();
  return json;
}

void RunSummary::Set(const std::string& key, const nlohmann::ordered_json& value) {
  ReadInto(nlohmann::ordered_json{{key, value}}, "summary.json's " + key);
}

std::string RunSummary::Text() const { return files::JsonText(Json()) + "\n"; }

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

namespace {

/// What the bus brought that the run did not use: rejected, conflicting, refused and bad messages.
void AddMessageAccounting(const RunOutcome& outcome, RunSummary* summary) {
  summary->rejected_commands = outcome.rejected_commands;
  summary->command_conflicts = outcome.command_conflicts;
  nlohmann::json other_worlds = nlohmann::json::array();
  for (int64_t id : outcome.other_worlds) other_worlds.push_back(lcm::RunIdText(id));
  summary->other_worlds = other_worlds;
  summary->robots_ever_lost = outcome.robots_ever_lost;
  // nlohmann::json (not ordered): the ids as text keys, in text order, as summary.json has always had them.
  nlohmann::json faults = nlohmann::json::object();
  for (const auto& [id, detail] : outcome.robot_faults) faults[std::to_string(id)] = detail;
  summary->robot_faults = faults;
  summary->robots_done = outcome.robots_done;
  summary->bad_messages = outcome.bad_messages;
  summary->bad_message_senders = outcome.bad_message_senders;
  nlohmann::json refused = nlohmann::json::object();
  for (const auto& [channel, seen] : outcome.refused) {
    refused[channel] = {{"count", seen.count}, {"first_step", seen.first_step}};
  }
  summary->refused_messages = refused;
  // Only the file's name: it lies beside the log, as `log` does.
  summary->refused_log = std::filesystem::path(outcome.refused_log).filename().string();
  summary->refused_log_events = outcome.refused_log_events;
  summary->bad_message_first = outcome.bad_message_first;
  summary->handler_failures = outcome.handler_failures;
  summary->dropped_messages = outcome.dropped_messages;
}

/// world.realism: its models, and what the tracker model did to the agents' view.
void AddRealism(const run_config::RunConfig& config, const world::RealisticWorld& realistic, RunSummary* summary) {
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
  summary->realism = realism;
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
  summary->realism_stats = {{"dropped_measurements", realistic.dropped_measurements()},
                            {"robots_lost_to_tracker", lost},
                            {"late_steps", realistic.late_steps()},
                            {"loop_stalls", realistic.stalls()},
                            {"late_time_s", realistic.late_time_s()},
                            {"robot_traits", robots}};
}

}  // namespace

RunSummary RunSummary::Of(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                          const std::string& log_file_name, const world::RunJudgement& judgement) {
  RunSummary summary;
  summary.run = config.name;
  summary.config = config.source;
  summary.seed = config.seed;
  summary.mode = config::WorldModeName(config.sim.mode);
  summary.robots = config.num_robots;
  summary.sim_only = config.sim_only;
  summary.end = outcome.end;
  summary.reason = outcome.reason;
  summary.steps = outcome.steps;
  summary.max_steps = config.sim.max_steps;
  summary.simulated_time_s = world.time_s();
  summary.wall_time_s = outcome.wall_time_s;
  summary.steps_per_second = outcome.wall_time_s > 0 ? static_cast<double>(outcome.steps) / outcome.wall_time_s : 0.0;
  summary.violations = world.violations();
  summary.SetVerdict(judgement);
  summary.run_id = lcm::RunIdText(outcome.run_id);
  AddMessageAccounting(outcome, &summary);
  summary.log = log_file_name;
  summary.log_events = outcome.log_events;
  // Where the robots really ended: a realistic world's poses() are what the
  // agents were sent last (measured), its true_poses() where they are.
  const auto* realistic = dynamic_cast<const world::RealisticWorld*>(&world::SteppingWorldOf(world));
  nlohmann::json poses = nlohmann::json::array();
  for (const world::Pose2& pose : realistic != nullptr ? realistic->true_poses() : world.poses()) {
    poses.push_back({pose.x_m, pose.y_m, pose.theta_rad});
  }
  summary.final_poses = poses;
  if (realistic != nullptr) AddRealism(config, *realistic, &summary);
  // Every field of the list is this summary's (the sections others add are theirs to set).
  const nlohmann::ordered_json written = summary.Json();
  for (auto it = written.begin(); it != written.end(); ++it) summary.present_.insert(it.key());
  return summary;
}

}  // namespace dream::node
