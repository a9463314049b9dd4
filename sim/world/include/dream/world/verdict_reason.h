#pragma once

#include <string>

#include "dream/world/run_verdict.h"

namespace dream::world {

/// One reason a run is not clean: which rule, how bad, what happened and
/// where to look. summary.json lists them under "verdict_reasons".
struct VerdictReason {
  /// Machine-readable name, e.g. "collision", "lost_robots", "goal",
  /// "verifier_too_close" (docs/run-outputs.md lists them all).
  std::string rule;
  /// The verdict this reason alone gives the run: kWarning, kNotReady or kRejected.
  RunVerdict verdict = RunVerdict::kNotReady;
  /// What is wrong, one line.
  std::string problem;
  /// How to find out more: a command or a summary.json field.
  std::string find_out;

  /// "<rule>: <problem> (more: <find_out>)".
  std::string Text() const;
};

}  // namespace dream::world
