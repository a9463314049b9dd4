// The Robotarium's start-up drive (world::StartupDrive) on real configs: every
// shipped config the lab can start (at most 22 robots) settles from several
// random charger placements; tests/data/startup_crowded.yaml deadlocks, and
// the failure names robots and distances.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/run_config/run_config.h"
#include "dream/run_config/startup_drive_cache.h"
#include "dream/world/startup_drive.h"
#include "dream/world/startup_drive_trials.h"
#include "../support/scratch_folder.h"
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

namespace dream::run_config {
namespace {

// Issue 33 item 3: a run's start-up drive check is kept in the user's cache,
// so a repeat run of the same start poses and seed skips the drives.
class StartupDriveCacheTest : public ::testing::Test {
 protected:
  dream::testing::ScratchFolder folder_{"dream_startup_drive_cache_test"};
  const StartupDriveCache cache_{folder_.path().string()};
  const RunConfig config_ = LoadRunConfigFile(dream::testing::SourceDir() + "/config/go_to_goal.yaml");
  std::vector<uint64_t> Seeds(uint64_t run_seed) const {
    std::vector<uint64_t> seeds;
    for (int i = 0; i < world::StartupDriveTrials::kPlacements; ++i) {
      seeds.push_back(world::StartupDriveTrials::PlacementSeed(run_seed, i));
    }
    return seeds;
  }
};

TEST_F(StartupDriveCacheTest, ARepeatCheckReadsWhatTheFirstDroveAndStored) {
  const std::string key = StartupDriveCache::KeyText(config_.world, config_.initial_poses, Seeds(config_.seed));
  EXPECT_FALSE(cache_.Find(key).has_value());
  const world::StartupDriveTrials driven = cache_.Trials(config_.world, config_.initial_poses, config_.seed);
  ASSERT_TRUE(std::filesystem::exists(cache_.FileOf(key)));
  const std::optional<world::StartupDriveTrials> cached = cache_.Find(key);
  ASSERT_TRUE(cached.has_value());
  EXPECT_EQ(cached->Describe(), driven.Describe());
  ASSERT_EQ(cached->tried(), driven.tried());
  for (int i = 0; i < driven.tried(); ++i) {
    EXPECT_EQ(cached->results()[i].seed, driven.results()[i].seed);
    EXPECT_EQ(cached->results()[i].steps, driven.results()[i].steps);
    EXPECT_EQ(cached->results()[i].settled, driven.results()[i].settled);
  }
  // Another seed, or start poses a bit apart, is another entry.
  EXPECT_NE(StartupDriveCache::KeyText(config_.world, config_.initial_poses, Seeds(config_.seed + 1)), key);
  std::vector<world::Pose2> moved = config_.initial_poses;
  moved[0].x_m = std::nextafter(moved[0].x_m, 10.0);
  EXPECT_NE(StartupDriveCache::KeyText(config_.world, moved, Seeds(config_.seed)), key);
}

TEST_F(StartupDriveCacheTest, ADamagedOrForeignEntryIsIgnoredAndDrivenAgain) {
  const std::string key = StartupDriveCache::KeyText(config_.world, config_.initial_poses, Seeds(config_.seed));
  const world::StartupDriveTrials driven = cache_.Trials(config_.world, config_.initial_poses, config_.seed);
  const std::string path = cache_.FileOf(key);
  const std::string whole = files::ReadFileText(path);
  for (const std::string& damaged :
       {whole.substr(0, whole.size() / 2), std::string("[]"), std::string("{\"key\": 1, \"results\": []}"),
        nlohmann::json{{"key", key},
                       {"results", {{{"seed", -1}, {"settled", true}, {"steps", 3}, {"misses", {}}, {"refusal", ""}}}}}
            .dump()}) {
    files::WriteFileAtomically(path, damaged);
    EXPECT_FALSE(cache_.Find(key).has_value()) << damaged;
    // Driven again, and stored whole once more.
    EXPECT_EQ(cache_.Trials(config_.world, config_.initial_poses, config_.seed).Describe(), driven.Describe());
    EXPECT_TRUE(cache_.Find(key).has_value());
  }
  // An entry of another key under this key's name (a hash collision) is not this key's.
  nlohmann::json other = nlohmann::json::parse(whole);
  other["key"] = key + " and more";
  files::WriteFileAtomically(path, other.dump());
  EXPECT_FALSE(cache_.Find(key).has_value());
}

TEST_F(StartupDriveCacheTest, NoFolderKeepsNothing) {
  const StartupDriveCache none("");
  EXPECT_EQ(none.Trials(config_.world, config_.initial_poses, config_.seed).tried(),
            world::StartupDriveTrials::kPlacements);
  EXPECT_FALSE(none.Find(StartupDriveCache::KeyText(config_.world, config_.initial_poses, Seeds(1))).has_value());
}

}  // namespace
}  // namespace dream::run_config
