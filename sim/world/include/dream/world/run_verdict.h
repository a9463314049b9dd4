#pragma once

#include <optional>
#include <string>

namespace dream::world {

/// What a run is worth on the Robotarium, from best to worst (the order is
/// used: a run's verdict is the worst of its reasons'). The first three are
/// what the Robotarium simulator's debug() says about the poses; kNotReady
/// is ours: the poses pass, but the run went wrong in a way debug() cannot
/// see (robots lost, command conflicts, bad messages, its goal not met).
enum class RunVerdict {
  kClean,     // no errors, no warnings
  kWarning,   // only actuator-limit errors: the run is accepted
  kNotReady,  // the lab's checks pass, but the run is not the experiment it should be
  kRejected,  // boundary or collision errors (or virtual-obstacle overlaps), or a lab verifier rule broken
};

/// "clean", "warning", "not_ready", "rejected" (summary.json's words).
const char* RunVerdictName(RunVerdict verdict);

/// The verdict RunVerdictName names; none for any other text. The one way C++
/// reads a verdict back from JSON (summary.json, a sweep's rows, a runner's report).
std::optional<RunVerdict> ParseRunVerdict(const std::string& name);

}  // namespace dream::world
