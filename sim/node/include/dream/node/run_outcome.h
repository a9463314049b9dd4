#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "dream/node/refused_record.h"

namespace dream::node {

/// How a run ended and what happened on the way; what the summary reports.
struct RunOutcome {
  enum class End {
    kFinished,      ///< reached max_steps, or every robot reported done
    kInterrupted,   ///< Ctrl-C / SIGTERM
    kStartTimeout,  ///< some robot never got an agent
    kFailed,        ///< an error stopped the run, e.g. the run log could not be written (see reason)
  };
  End end = End::kFinished;
  std::string reason;             ///< one line, for humans
  int64_t steps = 0;              ///< world steps taken
  double wall_time_s = 0.0;       ///< from the first published step to the end
  int64_t rejected_commands = 0;  ///< absurd, unknown robot, second agent, wrong step, another run
  /// Commands for a robot and step that already had a different command (a
  /// second sender, or a forged copy of an agent's id): refused, the first is
  /// applied (the log's DREAM_APPLIED says which).
  int64_t command_conflicts = 0;
  int64_t run_id = 0;  ///< this run's identifier, in every world message
  /// Run ids of other worlds seen publishing or commanded on the same bus
  /// (at most SimNode::kMaxOtherWorlds): a second `dream sim` on one URL.
  std::set<int64_t> other_worlds;
  std::set<int> robots_ever_lost;  ///< robots whose agent went silent at some point
  /// Robots whose controller failed (their agent said so on DREAM_FAULT_<id>):
  /// id -> "step k: what failed". They are lost and stopped from that step.
  std::map<int, std::string> robot_faults;
  std::set<int> robots_done;  ///< robots whose last command said done
  /// Undecodable or refused messages per channel; past lcm::BadMessageLog's
  /// cap the rest are counted under "(other channels)".
  std::map<std::string, long> bad_messages;
  /// Per channel of bad_messages, the first one: "step k: what was wrong".
  std::map<std::string, std::string> bad_message_first;
  /// Per channel of bad_messages, the agent ids that sent them (when the messages carry one).
  std::map<std::string, std::set<int64_t>> bad_message_senders;
  /// Messages the world heard and refused (kept out of the run log), per
  /// channel with the step of the first; RefusedRecord's caps apply.
  std::map<std::string, RefusedRecord::Channel> refused;
  /// The log of the first refused messages (RefusedRecord), if any was kept.
  std::string refused_log;
  int64_t refused_log_events = 0;
  long handler_failures = 0;  ///< exceptions caught in message handlers on the run's bus
  long dropped_messages = 0;  ///< messages the run's bus dropped, its queue full (memq://)
  int64_t log_events = 0;     ///< events written to the run log

  bool ok() const { return end == End::kFinished; }
};

const char* EndName(RunOutcome::End end);

}  // namespace dream::node
