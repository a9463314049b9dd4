#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/startup_drive_result.h"
#include "dream/world/world_params.h"

namespace dream::world {

// The Robotarium V2 start-up drive (rps/robotarium.py initialize(), which the
// lab runs before every experiment): the robots come off randomly chosen
// charger slots (rps/utilities/misc.py generate_initial_poses: 11 x positions
// on each long edge, 22 slots) and drive onto their start poses with the
// hybrid pose controller (HybridPoseController) under the unicycle barrier
// certificate without boundary (barriers::UnicycleBarrierParams::Rps()), a
// robot stuck for 150 steps being sent to a random waypoint within 0.25 m
// until it has moved 0.1 m, until every robot is within 0.05 m and 0.2 rad of
// its start pose. Each step is UnicycleWorld's (saturation, Euler step, atan2
// wrap). The official drive has no step limit; check-submission gives it
// MaxSteps() and so does this one.
//
// The placement and the waypoints are drawn from std::mt19937_64 seeded
// here, not from Python's streams: the same seed gives the same drive on
// every platform, but not the official simulator's drive (the stand-in of
// check-submission reproduces that one). Like rps's drive, it ignores DREAM's
// virtual obstacles and counts no Robotarium errors.
class StartupDrive {
 public:
  // rps's generate_initial_poses: 11 positions along each of the two long edges.
  static constexpr int kChargerSlots = 22;
  // Raised with every change that alters any drive's result: run_config's
  // StartupDriveCache keys its files on it, so no result of an older drive is reused.
  static constexpr int kRevision = 1;
  // rps's create_at_pose(position_error=0.05, rotation_error=0.2).
  static constexpr double kAtPositionM = 0.05;
  static constexpr double kAtHeadingRad = 0.2;

  // check-submission's --startup-max-steps default (STARTUP_MAX_STEPS in
  // bridge/python/run_submission.py, read from there when building).
  static int MaxSteps();

  // Called after every step of the drive with the step's number (1 = the
  // official first, still step) and the poses after it.
  using StepObserver = std::function<void(int step, const std::vector<Pose2>& poses)>;

  // Throws std::invalid_argument if the world params are invalid, a start
  // pose is not finite or max_steps < 1.
  StartupDrive(const WorldParams& world, std::vector<Pose2> start_poses, int max_steps = MaxSteps());

  // The drive from charger slots drawn from `seed`.
  StartupDriveResult Run(uint64_t seed, const StepObserver& observer = {}) const;
  // The drive from the given charger poses (one per robot); `seed` draws the waypoints.
  StartupDriveResult RunFrom(const std::vector<Pose2>& charger_poses, uint64_t seed,
                             const StepObserver& observer = {}) const;

  // The 22 slots in rps's order (x from left to right, bottom edge then top
  // edge at each x), facing into the arena.
  static std::vector<Pose2> ChargerSlots(const WorldParams& world);
  // num_robots distinct slots drawn from `seed` (rps: random.sample). Throws
  // std::invalid_argument for more than kChargerSlots robots.
  static std::vector<Pose2> PlaceOnChargers(const WorldParams& world, int num_robots, uint64_t seed);

  const std::vector<Pose2>& start_poses() const { return start_poses_; }
  int max_steps() const { return max_steps_; }

 private:
  WorldParams world_;
  std::vector<Pose2> start_poses_;
  int max_steps_;
};

}  // namespace dream::world
