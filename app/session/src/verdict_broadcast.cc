#include "dream/session/verdict_broadcast.h"

#include <spdlog/spdlog.h>

#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
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
  const int size = message.getEncodedSize();
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  message.encode(bytes.data(), 0, size);
  try {
    lcm.Publish(lcm::kVerdictChannel, bytes.data(), size);
  } catch (const std::exception& e) {
    spdlog::warn("{}: the verdict could not be published ({}); summary.json has it", lcm::kVerdictChannel, e.what());
  }
  if (log_path.empty()) return;
  try {
    node::AppendLogEvent(log_path, log_events, lcm::kVerdictChannel, message.utime, bytes.data(), size);
  } catch (const std::exception& e) {
    spdlog::warn("{}; the log ends without the run's verdict (summary.json has it)", e.what());
  }
}

void VerdictBroadcast::Resend(lcm::LcmInterface& lcm, const std::string& summary_path, double time_step_s,
                              ExitCode exit_code) {
  const node::RunSummary summary = node::RunSummary::Read(summary_path);
  const auto utime = static_cast<int64_t>(std::llround(static_cast<double>(summary.steps) * time_step_s * 1e6));
  RunResult result;
  result.outcome.steps = summary.steps;
  result.judgement.Add(summary.verdict_reasons);
  result.goal = summary.goal;
  const int64_t run_id = static_cast<int64_t>(std::stoull(summary.run_id, nullptr, 16));
  run_verdict_t message = MessageOf(result, run_id, utime, exit_code);
  message.verdict = VerdictValue(summary.verdict);  // as summary.json says it, whatever its reasons
  Send(lcm, message, std::string(), 0);
}

}  // namespace dream::session
