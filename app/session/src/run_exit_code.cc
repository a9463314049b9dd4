#include "dream/session/run_exit_code.h"

#include <spdlog/spdlog.h>

namespace dream::session {

ExitCode ExitCodeOf(world::RunVerdict verdict) {
  switch (verdict) {
    case world::RunVerdict::kRejected:
      return kExitRejected;
    case world::RunVerdict::kNotReady:
      return kExitNotReady;
    case world::RunVerdict::kClean:
    case world::RunVerdict::kWarning:
      break;
  }
  return kExitOk;
}

ExitCode ExitCodeOf(const node::RunOutcome& outcome, const world::RunJudgement& judgement, bool log_failure) {
  switch (outcome.end) {
    case node::RunOutcome::End::kFinished:
      break;
    case node::RunOutcome::End::kInterrupted:
      return kExitInterrupted;
    case node::RunOutcome::End::kStartTimeout:
    case node::RunOutcome::End::kFailed:
      if (log_failure) spdlog::error("{}", outcome.reason);
      return kExitRunFailed;
  }
  // A robot whose controller failed makes the run fail, whatever the rest did.
  if (!outcome.robot_faults.empty()) return kExitRunFailed;
  return ExitCodeOf(judgement.verdict());
}

ExitCode ExitCodeOf(const RunResult& result, bool log_failure) {
  if (!result.summary_written) return kExitRunFailed;  // the session said which output, and why
  const ExitCode code = ExitCodeOf(result.outcome, result.judgement, log_failure);
  return result.picture_failed ? kExitRunFailed : code;
}

bool RanToAVerdict(int code) { return code == kExitOk || code == kExitRejected || code == kExitNotReady; }

}  // namespace dream::session
