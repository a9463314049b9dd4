#pragma once

#include <cstdint>
#include <vector>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/verdict_reason.h"

namespace dream::world {

/// The rules by which the Robotarium's verifier refuses a submission before
/// it reaches the robots (robotarium/robotarium_matlab_verifier, Robotarium.m
/// and config/config.json; see docs/robotarium.md#the-labs-verifier):
///
///  - the robot count the script asks for must equal the declared one
///    ("MismatchingNumbers");
///  - robots too close, counted once per pair and iteration, or outside the
///    arena, counted once per robot and iteration, for more than 100 counts
///    each ("RobotsTooClose", "RobotsOutsideBoundaries": the verifier's text
///    says "iterations"; 100 exactly still passes);
///  - iterations x 0.033 s over 1.5 x the declared duration ("ExceededDuration");
///  - and the lab's own cap: an experiment (the declared duration, and the
///    run itself) of at most 900 s (15 minutes).
///
/// What is "declared" is what `dream export` writes into UPLOAD.txt from the
/// submission's parameters: the robot count and (experiment steps + settle
/// steps) x 0.033 s. `dream import` holds a lab run to that, or to what the
/// user says was declared (--declared-robots, --declared-duration).
struct LabVerifierRules {
  /// What the user declares when submitting.
  struct Declaration {
    int num_robots = 0;
    double duration_s = 0.0;
  };
  /// What the verifier counts while the script runs.
  struct Counts {
    int num_robots = 0;                     ///< robots the script asks the Robotarium for
    int64_t iterations = 0;                 ///< step() calls
    int64_t robots_too_close = 0;           ///< summed over iterations, one per pair (our collision_errors)
    int64_t robots_outside_boundaries = 0;  ///< summed over iterations, one per robot outside
  };

  int64_t robots_too_close_limit = 100;           ///< config.json robots_too_close_limit
  int64_t robots_outside_boundaries_limit = 100;  ///< config.json robots_outside_boundaries_limit
  double duration_factor = 1.5;                   ///< Robotarium.m: iteration*0.033 > 1.5*duration
  double max_duration_s = robotarium::RobotariumConstants::kMaxExperimentSeconds;  ///< the lab's 15-minute cap
  double time_step_s = robotarium::RobotariumConstants::kTimeStepSeconds;

  /// The settle steps `dream export` adds by default (ExportOptions), so that
  /// a simulated run is judged with the duration its export would declare.
  static constexpr int64_t kExportSettleSteps = 240;

  /// One kRejected reason per broken rule: verifier_robot_count,
  /// verifier_too_close, verifier_out_of_bounds, verifier_duration,
  /// lab_duration_cap. Empty when the verifier would pass the run.
  std::vector<VerdictReason> Check(const Declaration& declared, const Counts& counts) const;
};

}  // namespace dream::world
