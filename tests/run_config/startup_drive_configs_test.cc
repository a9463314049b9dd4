// The Robotarium's start-up drive (world::StartupDrive) on real configs: every
// shipped config the lab can start (at most 22 robots) settles from several
// random charger placements; tests/data/startup_crowded.yaml deadlocks, and
// the failure names robots and distances.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "dream/run_config/run_config.h"
#include "dream/world/startup_drive.h"
#include "dream/world/startup_drive_trials.h"
#include "../support/source_tree.h"

namespace dream::run_config {
namespace {

using ::testing::HasSubstr;

std::vector<std::string> ShippedConfigs() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::directory_iterator(dream::testing::SourceDir() + "/config")) {
    if (entry.path().extension() == ".yaml") paths.push_back(entry.path().string());
  }
  return paths;
}

TEST(StartupDriveConfigsTest, EveryShippedConfigTheLabCanStartSettles) {
  int driven = 0;
  for (const std::string& path : ShippedConfigs()) {
    const RunConfig config = LoadRunConfigFile(path);
    if (config.num_robots > world::StartupDrive::kChargerSlots) continue;
    const world::StartupDriveTrials trials =
        world::StartupDriveTrials::Try(config.world, config.initial_poses, config.seed);
    EXPECT_TRUE(trials.AllSettled()) << path << ": " << trials.Describe();
    ++driven;
  }
  EXPECT_GE(driven, 8);  // config/ ships nine configs of 6 to 15 robots
}

TEST(StartupDriveConfigsTest, TheCrowdedConfigDeadlocksNamingRobots) {
  const RunConfig config = LoadRunConfigFile(dream::testing::SourceDir() + "/tests/data/startup_crowded.yaml");
  const world::StartupDriveTrials trials =
      world::StartupDriveTrials::Try(config.world, config.initial_poses, config.seed, 1);
  EXPECT_EQ(trials.settled(), 0);
  const std::string text = trials.Describe();
  EXPECT_THAT(text, HasSubstr("settled from 0 of 1"));
  EXPECT_THAT(text, HasSubstr("after 6000 steps"));
  EXPECT_THAT(text, ::testing::ContainsRegex("robot [0-9] [0-9.]+ m / -?[0-9.]+ rad"));
}

}  // namespace
}  // namespace dream::run_config
