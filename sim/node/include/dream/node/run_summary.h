#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "dream/node/run_outcome.h"
#include "dream/run_config/run_config.h"
#include "dream/world/located_violation.h"
#include "dream/world/run_judgement.h"
#include "dream/world/run_verdict.h"
#include "dream/world/verdict_reason.h"
#include "dream/world/violation_counts.h"
#include "dream/world/world.h"

namespace dream::node {

/// summary.json, typed: the machine-readable summary of a run (how it ended,
/// steps, wall time, the Robotarium's violation counts, the verdict with its
/// reasons, debug()'s verdict and text, rejected commands, lost agents, bad
/// messages per channel, handler exceptions, final poses, and the sections
/// others add: metrics, goal, violations_located, realism, lab, agents).
/// docs/run-outputs.md describes every field.
///
/// ListFields is the one list of its fields, in the file's order: the writer
/// (session::RunReporter, through Json()/Text()) and every reader (Read())
/// go through it, as a kind's params go through theirs. The sections other
/// code owns (metrics, goal, ...) stay JSON of the kind (object or list) the
/// list says; keys the list does not name (lab, lab_replay, agents) are kept
/// in `sections` and written last, in order.
class RunSummary {
 public:
  /// summary.json larger than this is refused: no run writes one near it.
  static constexpr size_t kMaxBytes = size_t{64} << 20;
  static constexpr const char* kFileName = "summary.json";

  /// What a Section field holds.
  enum class JsonKind { kObject, kArray };

  std::string run;
  std::string config;
  uint64_t seed = 0;
  std::string mode;
  int64_t robots = 0;
  bool sim_only = false;  // declared for simulation only: never a lab-ready run
  RunOutcome::End end = RunOutcome::End::kFinished;
  std::string reason;
  int64_t steps = 0;
  int64_t max_steps = 0;
  double simulated_time_s = 0.0;
  double wall_time_s = 0.0;
  double steps_per_second = 0.0;
  world::ViolationCounts violations;
  nlohmann::ordered_json violations_located;  ///< null: not written
  world::RunVerdict verdict = world::RunVerdict::kClean;
  std::vector<world::VerdictReason> verdict_reasons;
  world::RunVerdict robotarium_verdict = world::RunVerdict::kClean;
  std::string robotarium_report;
  std::string run_id;
  int64_t rejected_commands = 0;
  int64_t command_conflicts = 0;
  nlohmann::ordered_json other_worlds = nlohmann::ordered_json::array();
  nlohmann::ordered_json robots_ever_lost = nlohmann::ordered_json::array();
  nlohmann::ordered_json robot_faults = nlohmann::ordered_json::object();
  nlohmann::ordered_json robots_done = nlohmann::ordered_json::array();
  nlohmann::ordered_json bad_messages = nlohmann::ordered_json::object();
  nlohmann::ordered_json bad_message_senders = nlohmann::ordered_json::object();
  nlohmann::ordered_json refused_messages = nlohmann::ordered_json::object();
  std::string refused_log;
  int64_t refused_log_events = 0;
  nlohmann::ordered_json bad_message_first = nlohmann::ordered_json::object();
  int64_t handler_failures = 0;
  int64_t dropped_messages = 0;
  std::string log;
  int64_t log_events = 0;
  nlohmann::ordered_json final_poses = nlohmann::ordered_json::array();
  nlohmann::ordered_json realism;        ///< null: not written (world.realism off)
  nlohmann::ordered_json realism_stats;  ///< null: not written
  nlohmann::ordered_json metrics;        ///< null: not written
  nlohmann::ordered_json goal;           ///< null: not written
  /// Keys ListFields does not name, written last in order (lab, lab_replay, agents).
  nlohmann::ordered_json sections = nlohmann::ordered_json::object();

  /// summary.json's fields, in its order. A visitor has Text, Whole (with the
  /// least value), Unsigned, Number, Flag, Choice (with the names), Counts,
  /// Reasons and Section (with its JsonKind) for each field.
  template <typename Visitor>
  void ListFields(Visitor& v) {
    v.Text("run", run);
    v.Text("config", config);
    v.Unsigned("seed", seed);
    v.Text("mode", mode);
    v.Whole("robots", robots, 0);
    v.Flag("sim_only", sim_only);
    v.Choice("end", end, EndNames(), "end");
    v.Text("reason", reason);
    v.Whole("steps", steps, 0);
    v.Whole("max_steps", max_steps, 0);
    v.Number("simulated_time_s", simulated_time_s);
    v.Number("wall_time_s", wall_time_s);
    v.Number("steps_per_second", steps_per_second);
    v.Counts("violations", violations);
    v.Section("violations_located", violations_located, JsonKind::kObject);
    v.Choice("verdict", verdict, VerdictNames(), "verdict");
    v.Reasons("verdict_reasons", verdict_reasons);
    v.Choice("robotarium_verdict", robotarium_verdict, VerdictNames(), "verdict");
    v.Text("robotarium_report", robotarium_report);
    v.Text("run_id", run_id);
    v.Whole("rejected_commands", rejected_commands, 0);
    v.Whole("command_conflicts", command_conflicts, 0);
    v.Section("other_worlds", other_worlds, JsonKind::kArray);
    v.Section("robots_ever_lost", robots_ever_lost, JsonKind::kArray);
    v.Section("robot_faults", robot_faults, JsonKind::kObject);
    v.Section("robots_done", robots_done, JsonKind::kArray);
    v.Section("bad_messages", bad_messages, JsonKind::kObject);
    v.Section("bad_message_senders", bad_message_senders, JsonKind::kObject);
    v.Section("refused_messages", refused_messages, JsonKind::kObject);
    v.Text("refused_log", refused_log);
    v.Whole("refused_log_events", refused_log_events, 0);
    v.Section("bad_message_first", bad_message_first, JsonKind::kObject);
    v.Whole("handler_failures", handler_failures, 0);
    v.Whole("dropped_messages", dropped_messages, 0);
    v.Text("log", log);
    v.Whole("log_events", log_events, 0);
    v.Section("final_poses", final_poses, JsonKind::kArray);
    v.Section("realism", realism, JsonKind::kObject);
    v.Section("realism_stats", realism_stats, JsonKind::kObject);
    v.Section("metrics", metrics, JsonKind::kObject);
    v.Section("goal", goal, JsonKind::kObject);
  }

  /// The summary of a run the world `world` stepped to its end, judged by `judgement`.
  static RunSummary Of(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                       const std::string& log_file_name, const world::RunJudgement& judgement);
  /// Reads summary.json at `path` (at most kMaxBytes, a regular file).
  /// A field that is missing keeps its default (Has() says which were there).
  /// @throws std::runtime_error naming the file, and the field and its bad
  ///         value when one is not what the list says (a verdict no verdict's
  ///         name, a count below 0, text where a number belongs).
  static RunSummary Read(const std::string& path);
  /// The same for JSON already parsed; `source` names it in errors.
  static RunSummary FromJson(const nlohmann::ordered_json& json, const std::string& source);

  /// Whether the file read had the field `key` (every field for a summary made by Of()).
  bool Has(const std::string& key) const { return present_.count(key) != 0; }
  /// Sets `key` to `value`: a field of the list in its place, checked as Read
  /// checks it (std::runtime_error naming the field and value), any other
  /// key as a section, last.
  void Set(const std::string& key, const nlohmann::ordered_json& value);
  /// verdict, verdict_reasons, robotarium_verdict and robotarium_report from `judgement`.
  void SetVerdict(const world::RunJudgement& judgement);
  /// As summary.json holds it: the fields in ListFields' order, then sections.
  nlohmann::ordered_json Json() const;
  /// Json() pretty-printed (files::JsonText), with its final newline: the file's text.
  std::string Text() const;

  static const std::vector<std::pair<const char*, RunOutcome::End>>& EndNames();
  static const std::vector<std::pair<const char*, world::RunVerdict>>& VerdictNames();

 private:
  /// Reads the fields `json` has (checked by the list) and keeps its other keys as sections.
  void ReadInto(const nlohmann::ordered_json& json, const std::string& source);

  std::set<std::string> present_;
};

/// A verdict reason as summary.json (and check.json) writes it: rule, verdict, problem, find_out.
nlohmann::ordered_json VerdictReasonJson(const world::VerdictReason& reason);
/// Sets `json`'s verdict, verdict_reasons, robotarium_verdict and robotarium_report as
/// RunSummary::SetVerdict does, for a report that is not a summary.json (check.json).
void SetSummaryVerdict(nlohmann::ordered_json* json, const world::RunJudgement& judgement);
/// summary.json's violations_located: {"listed": [{"kind", "robots", ("obstacle"),
/// "first_step", "last_step", "position": [x, y]}, ...], "unlisted": n, "max_listed": m}.
nlohmann::ordered_json ViolationsLocatedJson(const world::LocatedViolations& located, size_t max_listed);

}  // namespace dream::node
