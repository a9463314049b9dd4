#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "dream/lcm/lcm_interface.h"
#include "dream/run_verdict_t.hpp"
#include "dream/session/exit_code.h"
#include "dream/session/run_result.h"

namespace dream::session {

/// The one judge's verdict on the bus: once summary.json is written, the
/// world says on DREAM_VERDICT (run_verdict_t) what summary.json says (the
/// verdict, its reasons, the goal) and the exit code, and the run's log keeps
/// it as its last event. A viewer of the run (dream view, live or from a
/// replayed log) ends on it instead of a verdict of its own counts.
class VerdictBroadcast {
 public:
  /// Reasons carried, at most (summary.json lists them all).
  static constexpr size_t kMaxReasons = 64;
  /// Characters of a goal text or one reason, at most.
  static constexpr size_t kMaxTextChars = 1000;

  /// The message of a judged run: `result` (summary.json's verdict, reasons
  /// and goal), the run's id, its last simulated time and the exit code.
  static run_verdict_t MessageOf(const RunResult& result, int64_t run_id, int64_t utime, ExitCode exit_code);

  /// Publishes `message` on DREAM_VERDICT and appends it to the log at
  /// `log_path` (Record).
  static void Send(lcm::LcmInterface& lcm, const run_verdict_t& message, const std::string& log_path,
                   int64_t log_events);

  /// Appends `message` to the log at `log_path` ("": to none; event number
  /// `log_events`: the events already in it), for a run whose log is written
  /// without a bus (dream import). A log that cannot take it is warned about,
  /// naming the file; the run's outputs stand (summary.json has the verdict).
  static void Record(const run_verdict_t& message, const std::string& log_path, int64_t log_events);

  /// The verdict of a summary.json changed after its world published and
  /// logged it (dream launch's agents' reports, RunReporter::AddReasons):
  /// summary.json's as a message when the last DREAM_VERDICT of the log at
  /// `log_path` says otherwise (verdict, goal, reasons, exit code), that event
  /// then replaced by it (node::ReplaceLastLogEvent); none when the log says
  /// the same already, and then nothing is written. A log that does not end on
  /// this run's DREAM_VERDICT (a log the disk refused) is left as it is and
  /// the message returned. The caller publishes a message returned (Publish),
  /// so the log and a viewer both end on the verdict summary.json says, and
  /// opens no bus when none is. `time_step_s`: the run's step, for its last
  /// simulated time.
  /// @throws std::runtime_error naming the file when summary.json cannot be
  /// read, or the log cannot be rewritten.
  static std::optional<run_verdict_t> RewriteLoggedVerdict(const std::string& summary_path, double time_step_s,
                                                           ExitCode exit_code, const std::string& log_path);

  /// Publishes `message` on DREAM_VERDICT (a failure is warned about: summary.json has it).
  static void Publish(lcm::LcmInterface& lcm, const run_verdict_t& message);
};

}  // namespace dream::session
