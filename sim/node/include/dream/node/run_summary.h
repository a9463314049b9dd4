#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "dream/run_config/run_config.h"
#include "dream/world/run_judgement.h"
#include "dream/node/run_outcome.h"
#include "dream/world/located_violation.h"
#include "dream/world/world.h"

namespace dream::node {

/// The machine-readable summary of a run, as pretty-printed JSON: how it
/// ended, steps, wall time, the Robotarium's violation counts, the verdict
/// (clean / warning / not_ready / rejected) with its reasons, debug()'s own
/// verdict and text, rejected commands, lost agents, bad messages per
/// channel, handler exceptions, and final poses.
/// See docs/run-outputs.md for every field.
nlohmann::ordered_json RunSummary(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                                  const std::string& log_file_name, const world::RunJudgement& judgement);
/// Replaces a RunSummary's verdict fields (verdict, verdict_reasons,
/// robotarium_verdict, robotarium_report) in place, for a caller that judges
/// the run again once the summary exists (the experiment's goal is judged on it).
void SetSummaryVerdict(nlohmann::ordered_json* summary, const world::RunJudgement& judgement);
/// summary.json's violations_located: {"listed": [{"kind", "robots", ("obstacle"),
/// "first_step", "last_step", "position": [x, y]}, ...], "unlisted": n, "max_listed": m}.
nlohmann::ordered_json ViolationsLocatedJson(const world::LocatedViolations& located, size_t max_listed);
/// RunSummary as pretty-printed JSON text.
std::string RunSummaryJson(const run_config::RunConfig& config, const RunOutcome& outcome, const world::World& world,
                           const std::string& log_file_name, const world::RunJudgement& judgement);

}  // namespace dream::node
