#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dream/world/pose2.h"

namespace dream::world {

// What one start-up drive (StartupDrive) came to.
struct StartupDriveResult {
  // A robot that was not on its start pose when the drive ended.
  struct Miss {
    int robot_id = 0;
    double distance_m = 0.0;         // from its start position
    double heading_error_rad = 0.0;  // wrapped to [-pi, pi]
  };

  // Every robot within 0.05 m and 0.2 rad of its start pose within the step limit.
  bool settled = false;
  // Simulator steps taken, the official drive's first (still) step included:
  // what check-submission's step limit counts.
  int steps = 0;
  // The seed Run() drew the placement from (RunFrom: the one it drew waypoints from).
  uint64_t seed = 0;
  // Where the robots came off their chargers, and where the drive left them
  // (the experiment's step 0 when it settled).
  std::vector<Pose2> charger_poses;
  std::vector<Pose2> final_poses;
  // The robots not on their start poses at the end; empty when settled.
  std::vector<Miss> misses;
  // Why the drive could not start at all (more robots than charger slots); empty otherwise.
  std::string refusal;

  // "robot 3 0.412 m / 0.10 rad, robot 7 ..." (the misses), or the refusal.
  std::string DescribeMisses() const;
};

}  // namespace dream::world
