#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dream/world/located_violation.h"
#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/step_events.h"
#include "dream/world/world_params.h"

namespace dream::world {

class ViolationChecker;

/// Places the violations of one step's poses that come from elsewhere (a run
/// log, the bus), with the world's own checks (ViolationChecker): robots
/// outside the arena, robots too close, robots on an obstacle. The one code
/// behind the pictures' marks (render::LocateViolations) and the view's
/// (view::ViolationLocator, live and replay).
class StepViolationLocator {
 public:
  explicit StepViolationLocator(const WorldParams& world);
  ~StepViolationLocator();
  StepViolationLocator(const StepViolationLocator&) = delete;
  StepViolationLocator& operator=(const StepViolationLocator&) = delete;

  /// Checks `num_robots` poses given as a message carries them (x, y, theta
  /// per robot) among `obstacles` (those with a value that is not finite are
  /// left out) and appends each violation of step `step` to `found` (its
  /// first and last step that step). False, and nothing found, when the poses
  /// are not `num_robots` (at least one) finite poses (each found violation's
  /// worst_m is measured: see LocatedViolation): a forged message
  /// breaks no rule the checker can place. The robot count may change from
  /// one call to the next (the checker is remade).
  bool Locate(int64_t step, int num_robots, const std::vector<double>& x, const std::vector<double>& y,
              const std::vector<double>& theta, const std::vector<ObstacleState>& obstacles,
              std::vector<LocatedViolation>* found);

  /// The checker's events and the poses of the last step Locate() accepted.
  const StepEvents& last_step_events() const;
  const std::vector<Pose2>& last_poses() const { return poses_; }

 private:
  /// `v`'s measure at this step (LocatedViolation::worst_m), on the poses and obstacles Locate took.
  double Measure(const LocatedViolation& v) const;

  WorldParams world_;
  std::vector<Pose2> poses_;
  std::vector<ObstacleState> obstacles_;
  int checked_robots_ = 0;
  std::unique_ptr<ViolationChecker> checker_;  // remade when the robot count changes
};

/// Each event of `events` placed on `poses` (the poses its robot ids index):
/// a robot outside or on an obstacle where it is, a colliding pair at its
/// middle; an event naming a robot outside `poses` is left out.
void PlaceViolations(const StepEvents& events, const std::vector<Pose2>& poses, std::vector<LocatedViolation>* found);

}  // namespace dream::world
