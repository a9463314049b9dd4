#include "dream/node/run_judge.h"

#include <numeric>

#include "dream/lcm/channels.h"
#include "dream/world/lab_verifier_rules.h"
#include "dream/world/barrier_world.h"
#include "dream/world/realistic_world.h"

namespace dream::node {
namespace {

std::string IdList(const std::set<int>& ids) {
  std::string text;
  for (int id : ids) text += (text.empty() ? "" : ", ") + std::to_string(id);
  return text;
}

}  // namespace

std::vector<world::VerdictReason> OutcomeReasons(const RunOutcome& outcome) {
  std::vector<world::VerdictReason> reasons;
  if (outcome.end != RunOutcome::End::kFinished) {
    reasons.push_back({"did_not_finish", world::RunVerdict::kNotReady,
                       std::string("the run ended '") + EndName(outcome.end) + "': " + outcome.reason,
                       "summary.json end and reason"});
  }
  for (const auto& [id, detail] : outcome.robot_faults) {
    reasons.push_back({"controller_failed", world::RunVerdict::kNotReady,
                       "robot " + std::to_string(id) + " was lost, its controller failed at " + detail,
                       "summary.json robot_faults"});
  }
  std::set<int> silent;
  for (int id : outcome.robots_ever_lost) {
    if (outcome.robot_faults.count(id) == 0) silent.insert(id);
  }
  if (!silent.empty()) {
    reasons.push_back({"lost_robots", world::RunVerdict::kNotReady,
                       std::string(silent.size() == 1 ? "robot " : "robots ") + IdList(silent) +
                           " lost: the agent fell silent past agent_timeout_s and the world stopped the robot",
                       "summary.json robots_ever_lost; dream log echo RUN DREAM_STATUS shows lost_robot_ids by step"});
  }
  if (outcome.command_conflicts > 0) {
    reasons.push_back({"command_conflicts", world::RunVerdict::kNotReady,
                       std::to_string(outcome.command_conflicts) +
                           " commands for a robot and step that already had another one (a second sender); "
                           "the first was applied",
                       std::string("summary.json command_conflicts; dream log echo RUN ") + lcm::kAppliedChannel +
                           " says which command was applied"});
  }
  const long bad = std::accumulate(outcome.bad_messages.begin(), outcome.bad_messages.end(), 0L,
                                   [](long sum, const auto& entry) { return sum + entry.second; });
  if (bad > 0) {
    // What was refused, where, how many and from when: "bad messages" alone
    // does not tell a typo in a controller from forged traffic.
    std::string channels;
    int named = 0;
    for (const auto& [channel, count] : outcome.bad_messages) {
      if (named++ == 3) {
        channels += "; ...";
        break;
      }
      channels += (channels.empty() ? "" : "; ") + channel + ": " + std::to_string(count);
      const auto first = outcome.bad_message_first.find(channel);
      if (first != outcome.bad_message_first.end()) channels += ", the first at " + first->second;
    }
    reasons.push_back({"bad_messages", world::RunVerdict::kNotReady,
                       std::to_string(bad) + " undecodable or refused messages were dropped: " + channels,
                       outcome.refused_log.empty()
                           ? std::string("summary.json bad_messages, bad_message_first and bad_message_senders")
                           : "summary.json bad_messages, bad_message_first, bad_message_senders and refused_messages; "
                             "the first " +
                                 std::to_string(outcome.refused_log_events) + " as heard: dream log echo " +
                                 outcome.refused_log});
  }
  if (!outcome.other_worlds.empty()) {
    reasons.push_back(
        {"other_worlds", world::RunVerdict::kNotReady,
         std::to_string(outcome.other_worlds.size()) + " other world(s) published on the same LCM URL during the run",
         "summary.json other_worlds; give each run its own --lcm-url"});
  }
  if (outcome.handler_failures > 0) {
    reasons.push_back({"handler_failures", world::RunVerdict::kNotReady,
                       std::to_string(outcome.handler_failures) + " exceptions in message handlers (caught and logged)",
                       "summary.json handler_failures; the run's log lines"});
  }
  if (outcome.dropped_messages > 0) {
    reasons.push_back({"dropped_messages", world::RunVerdict::kNotReady,
                       std::to_string(outcome.dropped_messages) +
                           " messages were dropped by the in-process bus, its queue full (a message flood)",
                       "summary.json dropped_messages; the run's log lines"});
  }
  return reasons;
}

world::RunJudgement JudgeRun(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                             int64_t robots_outside_boundaries) {
  world::RunJudgement judgement(
      world::RunReport::FromViolations(world.step(), world.violations(), world.time_step_s()));
  world::LabVerifierRules rules;
  rules.time_step_s = world.time_step_s();
  // What the run's export would declare and run: its steps plus the settle phase.
  const int64_t iterations = world.step() + world::LabVerifierRules::kExportSettleSteps;
  const world::LabVerifierRules::Declaration declared{config.num_robots,
                                                      static_cast<double>(iterations) * world.time_step_s()};
  world::LabVerifierRules::Counts counts;
  counts.num_robots = world.num_robots();
  counts.iterations = iterations;
  counts.robots_too_close = world.violations().collision_errors;
  counts.robots_outside_boundaries =
      robots_outside_boundaries >= 0 ? robots_outside_boundaries : world.violations().boundary_errors;
  judgement.Add(rules.Check(declared, counts));
  judgement.Add(OutcomeReasons(outcome));
  // world.realism: a robot lost to the tracker (a warning: the lab runs it, blind).
  if (const auto* realistic = dynamic_cast<const world::RealisticWorld*>(&world::SteppingWorldOf(world))) {
    if (const std::optional<world::VerdictReason> lost = realistic->TrackerLossReason()) judgement.Add(*lost);
  }
  return judgement;
}

}  // namespace dream::node
