#pragma once

#include <cstdint>
#include <string>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/run_verdict.h"
#include "dream/world/violation_counts.h"

namespace dream::world {

// The end-of-run summary the Robotarium V2 simulator prints from debug().
struct RunReport {
  int64_t iterations = 0;
  // iterations * time step: what the run would take on the real testbed.
  double estimated_duration_s = 0.0;
  ViolationCounts violations{};
  RunVerdict verdict = RunVerdict::kClean;

  // Rejected if boundary + collision + obstacle overlaps > 0 (obstacle
  // overlaps are ours: a virtual obstacle stands for a real one, so touching
  // it is treated like a collision); Warning if only actuator errors.
  static RunReport FromViolations(int64_t iterations, const ViolationCounts& violations,
                                  double time_step_s = robotarium::RobotariumConstants::kTimeStepSeconds);

  // The text debug() prints, character for character when there are no
  // obstacle overlaps (those add one line of ours to the error list).
  std::string Text() const;
};

}  // namespace dream::world
