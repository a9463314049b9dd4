#include "dream/workflows/slurm_task_state.h"

namespace dream::workflows {

std::string SlurmTaskState::Why() const {
  switch (state) {
    case State::kPending:
      return "pending in Slurm";
    case State::kRunning:
      return "running in Slurm";
    case State::kCompleted:
      return "its Slurm task ended (" + word + ") without an exit record";
    case State::kCancelled:
      return "cancelled in Slurm (" + word + ")";
    case State::kTimedOut:
      return "Slurm's time limit for the task ran out (" + word + "; raise it with --slurm-option=--time=...)";
    case State::kFailed:
      break;
  }
  return "its Slurm task failed (" + word + ")";
}

std::optional<SlurmTaskState> SlurmTaskState::FromSlurmWord(const std::string& text) {
  const std::string word = text.substr(0, text.find(' '));  // "CANCELLED by 0" -> CANCELLED
  if (word.empty()) return std::nullopt;
  SlurmTaskState s;
  s.word = word;
  if (word == "PENDING" || word == "REQUEUED" || word == "REQUEUE_HOLD" || word == "REQUEUE_FED" ||
      word == "CONFIGURING" || word == "RESV_DEL_HOLD" || word == "SUSPENDED" || word == "STOPPED") {
    s.state = State::kPending;
  } else if (word == "RUNNING" || word == "COMPLETING" || word == "SIGNALING" || word == "STAGE_OUT" ||
             word == "RESIZING") {
    s.state = State::kRunning;
  } else if (word == "COMPLETED") {
    s.state = State::kCompleted;
  } else if (word == "CANCELLED" || word == "PREEMPTED" || word == "REVOKED" || word == "DEADLINE") {
    s.state = State::kCancelled;
  } else if (word == "TIMEOUT") {
    s.state = State::kTimedOut;
  } else {
    s.state = State::kFailed;  // FAILED, NODE_FAIL, OUT_OF_MEMORY, BOOT_FAIL, ...
  }
  return s;
}

std::optional<SlurmTaskState> SlurmTaskState::FromTaskLog(const std::string& log_tail) {
  const size_t marker = log_tail.rfind("*** JOB ");
  if (marker == std::string::npos) return std::nullopt;
  const std::string line = log_tail.substr(marker, log_tail.find('\n', marker) - marker);
  SlurmTaskState s;
  if (line.find("DUE TO TIME LIMIT") != std::string::npos) {
    s.state = State::kTimedOut;
    s.word = "TIMEOUT";
  } else if (line.find("DUE TO NODE FAILURE") != std::string::npos) {
    s.state = State::kFailed;
    s.word = "NODE_FAIL";
  } else if (line.find("DUE TO PREEMPTION") != std::string::npos) {
    s.state = State::kCancelled;
    s.word = "PREEMPTED";
  } else if (line.find("CANCELLED") != std::string::npos) {
    s.state = State::kCancelled;
    s.word = "CANCELLED";
  } else {
    return std::nullopt;
  }
  return s;
}

}  // namespace dream::workflows
