#include "dream/world/run_report.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>

#include "dream/world/printf_text.h"

namespace dream::world {
RunReport RunReport::FromViolations(int64_t iterations, const ViolationCounts& violations, double time_step_s) {
  RunReport report;
  report.iterations = iterations;
  report.estimated_duration_s = static_cast<double>(iterations) * time_step_s;
  report.violations = violations;
  if (violations.hard_errors() > 0) {
    report.verdict = RunVerdict::kRejected;
  } else if (violations.actuator_errors > 0) {
    report.verdict = RunVerdict::kWarning;
  } else {
    report.verdict = RunVerdict::kClean;
  }
  return report;
}

// The wording copies debug() in rps/robotarium.py, and "%.2f" / "%.0f" round
// like Python's format specs.
std::string RunReport::Text() const {
  std::string text =
      PrintfText("Your simulation took approximately %.2f real seconds to execute.\n\n", estimated_duration_s);
  switch (verdict) {
    case RunVerdict::kNotReady:  // never from counts alone (FromViolations); RunJudgement words it
    case RunVerdict::kClean:
      text += "No errors or warnings in your simulation!  Your script will run on the Robotarium!\n\n";
      break;
    case RunVerdict::kWarning: {
      const double percent =
          static_cast<double>(100 * violations.actuator_errors) / static_cast<double>(std::max<int64_t>(iterations, 1));
      text += "No hard errors detected, your script will run on the Robotarium!\n\n";
      text += PrintfText("WARNING: %" PRId64 " out of %" PRId64
                         " (~%.0f%%) timesteps had velocity command(s) exceed actuator limits.\n",
                         violations.actuator_errors, iterations, percent);
      text +=
          "         A large percentage of exceeded actuator commands will cause noticeable\n"
          "         differences between this simulation and the physical Robotarium.\n";
      break;
    }
    case RunVerdict::kRejected:
      text += "Errors detected, your script will NOT run on the Robotarium!\n\n";
      text += "Errors:\n";
      // The official wording says "time steps" although it counts pairs.
      if (violations.collision_errors > 0) {
        text +=
            PrintfText("\t Simulation had %" PRId64 " time steps where robots were too close (potential collision).\n",
                       violations.collision_errors);
      }
      if (violations.boundary_errors > 0) {
        text += PrintfText("\t Simulation had %" PRId64 " time steps where robots were outside boundaries.\n",
                           violations.boundary_errors);
      }
      if (violations.obstacle_collisions > 0) {
        text +=
            PrintfText("\t Simulation had %" PRId64 " robot-obstacle overlaps (robots touching virtual obstacles).\n",
                       violations.obstacle_collisions);
      }
      text += "\nPlease fix the noted errors in your simulation; otherwise, your experiment will be rejected.\n";
      break;
  }
  return text;
}

}  // namespace dream::world
