#pragma once

#include <nlohmann/json.hpp>

#include "dream/node/run_outcome.h"
#include "dream/world/run_judgement.h"
#include "dream/world/run_report.h"

namespace dream::session {

/// What one run of a RunSession came to: how the loop ended, the verdict
/// with its reasons (as summary.json says), and whether the run's outputs
/// were all written. The command turns it into its exit code.
struct RunResult {
  node::RunOutcome outcome;
  world::RunJudgement judgement{world::RunReport{}};
  /// summary.json's goal (ExperimentGoal::Json, with "judged"); null before it is judged.
  nlohmann::ordered_json goal;
  /// summary.json was written (a full disk may refuse it).
  bool summary_written = false;
  /// A picture was due (the run made a step or finished) and could not be drawn or written.
  bool picture_failed = false;
};

}  // namespace dream::session
