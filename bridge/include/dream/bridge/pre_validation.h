#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dream/bridge/run_track.h"
#include "dream/world/lab_verifier_rules.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/world_params.h"

namespace dream::bridge {

/// What the Robotarium accepts, as far as a recorded run can show it.
struct LabLimits {
  /// Robots on the hardware.
  int max_robots = robotarium::RobotariumConstants::kMaxRobotsOnHardware;
  /// The lab's cap on an experiment: iterations x 0.033 s (15 minutes).
  double max_duration_s = robotarium::RobotariumConstants::kMaxExperimentSeconds;
  /// Start poses must keep the whole robot (radius 0.055 m) inside the arena.
  double start_wall_margin_m = robotarium::RobotariumConstants::kRobotDiameterMeters / 2.0;
  /// The lab's start-up routine drives robots onto their start poses with a
  /// barrier certificate that keeps the points `start_projection_m` ahead of
  /// them 0.25 m apart and stops within 0.05 m of the target: start poses
  /// whose projected points are closer than this cannot all be reached.
  double start_spacing_m = 0.20;
  double start_projection_m = 0.05;
  /// Crowded start: a robot with this many others within crowd_radius_m. The
  /// official V2.0.0 start-up routine deadlocked (not placed after 4,000
  /// steps) on 15 robots packed 0.35 m apart in a corner; it placed 15 on a
  /// triangular lattice 0.40 m apart in 2,000-2,900 steps (three random
  /// seeds) and 15 spread 0.6 m apart in 1,141.
  double crowd_radius_m = 0.38;
  int crowd_neighbours = 3;
};

/// One reason the lab would refuse (or fail) the run.
struct ExportProblem {
  std::string rule;     ///< strategy, obstacle_schedule, robots, duration, finished, lost_robot, start_inside_arena,
                        ///< start_spacing, boundary, collision, obstacle, verifier_* (world::LabVerifierRules), or a
                        ///< summary.json verdict reason
  int robot = -1;       ///< the robot concerned, -1 for none
  int other = -1;       ///< the second robot of a pair, or the obstacle id
  int64_t step = -1;    ///< the first step concerned, -1 for none
  std::string problem;  ///< what is wrong
  std::string fix;      ///< how to fix it

  /// "<rule>: robot 3, step 120: <problem>. Fix: <fix>".
  std::string Text() const;
};

/// Checks a recorded run against the lab's rules, as the lab would judge the
/// submission made from it: 1..max_robots robots; (steps + settle steps) x
/// time step within the cap; a finished run with no robot lost at its end
/// (agent silent, controller failed); start poses inside the arena
/// and far enough apart for the start-up routine; and no boundary, collision
/// or virtual-obstacle error at any step (re-checked on the recorded poses,
/// so each problem names its first robot and step); and the lab verifier's
/// rules (world::LabVerifierRules: the declared robot count, robots too close
/// or outside more than 100 times, the script's iterations within 1.5 x the
/// declared duration). Empty when the run can be exported.
/// `experiment_steps` is how many steps the script may run: -1 for the
/// recorded ones (track, replay); the controller strategy runs up to the
/// run's step limit. `declared`: what the submission declares; by default
/// what UPLOAD.txt gives, the run's robot count and (experiment steps +
/// settle steps) x time step.
std::vector<ExportProblem> PreValidate(const RunTrack& track, const RunEnd& end, const world::WorldParams& world,
                                       int64_t settle_max_steps, const LabLimits& limits = {},
                                       int64_t experiment_steps = -1,
                                       const std::optional<world::LabVerifierRules::Declaration>& declared = {});

/// The lab verifier's counts on a recorded run, re-checked on its poses at
/// steps 0 .. last - 1 (those the simulator validated): robots too close
/// (pairs x steps, as the world's collision_errors) and outside the arena
/// (robots x steps: the verifier counts each robot, the Robotarium
/// simulator's boundary_errors each step). `iterations` and `num_robots`
/// are the track's steps and robots.
world::LabVerifierRules::Counts VerifierCounts(const RunTrack& track, const world::WorldParams& world);
/// The same on a run's log (RunTrackOf(log), without its status).
/// @throws std::runtime_error with the log's flaw when it is not a whole run.
world::LabVerifierRules::Counts VerifierCounts(const run_log::RunLog& log, const world::WorldParams& world);

/// Risks that do not make the lab refuse the run by rule but may make it fail:
/// start poses so crowded that the lab's start-up routine may deadlock before
/// step 0. One line each, with what to do (run dream check-submission in the
/// official simulator, which gives up on a deadlocked start-up).
std::vector<std::string> StartUpWarnings(const RunTrack& track, const LabLimits& limits = {});

}  // namespace dream::bridge
