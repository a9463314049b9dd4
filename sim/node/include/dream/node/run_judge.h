#pragma once

#include <cstdint>
#include <vector>

#include "dream/run_config/run_config.h"
#include "dream/world/run_judgement.h"
#include "dream/node/run_outcome.h"
#include "dream/world/world.h"

namespace dream::node {

/// What went wrong on the bus, as verdict reasons (all kNotReady):
/// did_not_finish, controller_failed, lost_robots (silent agents, not those
/// of controller_failed), command_conflicts, bad_messages, other_worlds,
/// handler_failures, dropped_messages. Empty for a healthy run.
std::vector<world::VerdictReason> OutcomeReasons(const RunOutcome& outcome);

/// The run's judgement: debug()'s verdict on the world's counts, the lab
/// verifier's rules (LabVerifierRules: declared = the config's robot count
/// and (steps + LabVerifierRules::kExportSettleSteps) x the time step, what
/// `dream export` would declare), OutcomeReasons, and for a RealisticWorld
/// the robots lost to its tracker (RealisticWorld::TrackerLossReason). The verifier counts
/// robots outside the arena once per robot and step; pass that count as
/// `robots_outside_boundaries` when known (re-checked on the log), else -1:
/// the world's boundary_errors (steps with any robot outside) is used, a
/// lower bound of it. The experiment's goal is judged by the caller (it
/// needs the metrics).
world::RunJudgement JudgeRun(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                             int64_t robots_outside_boundaries = -1);

}  // namespace dream::node
