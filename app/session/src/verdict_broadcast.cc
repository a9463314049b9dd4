#include "dream/session/verdict_broadcast.h"

#include <spdlog/spdlog.h>

#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/log_reader.h"
#include "dream/node/log_append.h"
#include "dream/node/run_summary.h"
#include "dream/session/experiment_goal.h"
#include "dream/world/run_verdict.h"

namespace dream::session {
namespace {

int8_t VerdictValue(world::RunVerdict verdict) {
  switch (verdict) {
    case world::RunVerdict::kClean:
      return run_verdict_t::CLEAN;
    case world::RunVerdict::kWarning:
      return run_verdict_t::WARNING;
    case world::RunVerdict::kNotReady:
      return run_verdict_t::NOT_READY;
    case world::RunVerdict::kRejected:
      break;
  }
  return run_verdict_t::REJECTED;
}

// summary.json's goal (ExperimentGoal::Json, with "judged") as the message's constant.
int8_t GoalValue(const nlohmann::ordered_json& goal) {
  if (!goal.is_object() || !goal.value("has_criterion", false)) return run_verdict_t::GOAL_NONE_DECLARED;
  if (!goal.value("judge_error", std::string()).empty()) return run_verdict_t::GOAL_JUDGE_FAILED;
  if (goal.value("met", false)) return run_verdict_t::GOAL_MET;
  if (goal.contains("judged") && goal["judged"] == false) return run_verdict_t::GOAL_NOT_JUDGED;
  return run_verdict_t::GOAL_MISSED;
}

// Cut at kMaxTextChars without splitting a UTF-8 character (the bus refuses text that is not UTF-8).
std::string Bounded(const std::string& text) {
  if (text.size() <= VerdictBroadcast::kMaxTextChars) return text;
  size_t end = VerdictBroadcast::kMaxTextChars;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;
  return text.substr(0, end) + "...";
}

std::vector<uint8_t> Encoded(const run_verdict_t& message) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

// Whether two verdict messages of a run tell the same: what a viewer shows and a script reads.
bool SaysTheSame(const run_verdict_t& a, const run_verdict_t& b) {
  return a.run_id == b.run_id && a.step == b.step && a.verdict == b.verdict && a.goal == b.goal &&
         a.exit_code == b.exit_code && a.goal_completion_step == b.goal_completion_step && a.goal_text == b.goal_text &&
         a.reasons == b.reasons;
}

// The log's last event when it is a DREAM_VERDICT of `run_id`; none for "" or any other log.
std::optional<run_verdict_t> LastVerdictOf(const std::string& log_path, int64_t run_id) {
  if (log_path.empty()) return std::nullopt;
  lcm::LogReader reader(log_path);
  lcm::LogRecord record;
  lcm::LogRecord last;
  while (reader.Next(&record)) last = std::move(record);
  run_verdict_t verdict;
  if (last.channel != lcm::kVerdictChannel ||
      !lcm::Decode(last.data.data(), static_cast<int>(last.data.size()), &verdict) || verdict.run_id != run_id) {
    spdlog::warn("{}: does not end on the run's {}; left as it is", log_path, lcm::kVerdictChannel);
    return std::nullopt;
  }
  return verdict;
}

}  // namespace

run_verdict_t VerdictBroadcast::MessageOf(const RunResult& result, int64_t run_id, int64_t utime, ExitCode exit_code) {
  run_verdict_t message{};
  message.utime = utime;
  message.step = result.outcome.steps;
  message.run_id = run_id;
  message.verdict = VerdictValue(result.judgement.verdict());
  message.goal = GoalValue(result.goal);
  message.exit_code = static_cast<int32_t>(exit_code);
  message.goal_completion_step =
      result.goal.is_object() && result.goal.contains("completion_step") && result.goal["completion_step"].is_number()
          ? result.goal["completion_step"].get<int64_t>()
          : -1;
  if (message.goal == run_verdict_t::GOAL_NOT_JUDGED) {
    message.goal_text = "not judged: --steps stopped the run first";
  } else {
    message.goal_text = Bounded(ExperimentGoal::Text(nlohmann::json(result.goal)));
  }
  size_t listed = 0;
  for (const world::VerdictReason& reason : result.judgement.reasons()) {
    if (listed++ == kMaxReasons) break;
    message.reasons += (message.reasons.empty() ? "" : "\n") + Bounded(reason.rule + ": " + reason.problem);
  }
  return message;
}

void VerdictBroadcast::Send(lcm::LcmInterface& lcm, const run_verdict_t& message, const std::string& log_path,
                            int64_t log_events) {
  Publish(lcm, message);
  Record(message, log_path, log_events);
}

void VerdictBroadcast::Publish(lcm::LcmInterface& lcm, const run_verdict_t& message) {
  const std::vector<uint8_t> bytes = Encoded(message);
  try {
    lcm.Publish(lcm::kVerdictChannel, bytes.data(), static_cast<int>(bytes.size()));
  } catch (const std::exception& e) {
    spdlog::warn("{}: the verdict could not be published ({}); summary.json has it", lcm::kVerdictChannel, e.what());
  }
}

void VerdictBroadcast::Record(const run_verdict_t& message, const std::string& log_path, int64_t log_events) {
  if (log_path.empty()) return;
  const std::vector<uint8_t> bytes = Encoded(message);
  try {
    node::AppendLogEvent(log_path, log_events, lcm::kVerdictChannel, message.utime, bytes.data(),
                         static_cast<int>(bytes.size()));
  } catch (const std::exception& e) {
    spdlog::warn("{}; the log ends without the run's verdict (summary.json has it)", e.what());
  }
}

std::optional<run_verdict_t> VerdictBroadcast::RewriteLoggedVerdict(const std::string& summary_path, double time_step_s,
                                                                    ExitCode exit_code, const std::string& log_path) {
  const node::RunSummary summary = node::RunSummary::Read(summary_path);
  const auto utime = static_cast<int64_t>(std::llround(static_cast<double>(summary.steps) * time_step_s * 1e6));
  RunResult result;
  result.outcome.steps = summary.steps;
  result.judgement.Add(summary.verdict_reasons);
  result.goal = summary.goal;
  const int64_t run_id = static_cast<int64_t>(std::stoull(summary.run_id, nullptr, 16));
  run_verdict_t message = MessageOf(result, run_id, utime, exit_code);
  message.verdict = VerdictValue(summary.verdict);  // as summary.json says it, whatever its reasons
  if (const std::optional<run_verdict_t> logged = LastVerdictOf(log_path, run_id)) {
    if (SaysTheSame(*logged, message)) return std::nullopt;
    message.utime = logged->utime;  // the log's order of time stays as the world wrote it
    const std::vector<uint8_t> bytes = Encoded(message);
    node::ReplaceLastLogEvent(log_path, lcm::kVerdictChannel, message.utime, bytes.data(),
                              static_cast<int>(bytes.size()));
  }
  return message;
}

}  // namespace dream::session
