#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/startup_drive_result.h"
#include "dream/world/world_params.h"

namespace dream::world {

// The start-up drive (StartupDrive) tried from several random placements:
// the lab's placement is random, so one drive that settles says little. What
// `dream run`, `sweep` and `export` ask before step 0.
class StartupDriveTrials {
 public:
  static constexpr int kPlacements = 5;

  // kPlacements drives (placement i seeded by PlacementSeed(run_seed, i)).
  static StartupDriveTrials Try(const WorldParams& world, const std::vector<Pose2>& start_poses, uint64_t run_seed,
                                int placements = kPlacements);
  // Placement i's seed from the run's seed; placement 0 is the drive
  // `world.start: placed` runs.
  static uint64_t PlacementSeed(uint64_t run_seed, int placement);

  // Trials already run (a cache's): `results` as Try gave them.
  static StartupDriveTrials Of(std::vector<StartupDriveResult> results);

  int tried() const { return static_cast<int>(results_.size()); }
  int settled() const;
  bool AllSettled() const { return settled() == tried(); }
  const std::vector<StartupDriveResult>& results() const { return results_; }
  // The most steps a settled drive took (0 if none settled).
  int MostSteps() const;

  // One line: "the start-up drive settled from 3 of 5 random charger
  // placements (at most 812 steps); from placement seed 123 after 6000 steps
  // robot 3 was 0.412 m / 0.10 rad from its start pose, ..." -- the first
  // failure's robots and distances.
  std::string Describe() const;

 private:
  std::vector<StartupDriveResult> results_;
};

}  // namespace dream::world
