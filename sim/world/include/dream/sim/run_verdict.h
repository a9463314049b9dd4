#pragma once

namespace dream::sim {

// What the Robotarium would make of a run, as its simulator's debug() says.
enum class RunVerdict {
  kClean,     // no errors, no warnings
  kWarning,   // only actuator-limit errors: the run is accepted
  kRejected,  // boundary or collision errors (or virtual-obstacle overlaps)
};

const char* RunVerdictName(RunVerdict verdict);

}  // namespace dream::sim
