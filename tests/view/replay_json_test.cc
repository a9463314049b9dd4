#include "dream/view/replay_json.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include <nlohmann/json.hpp>
#include <string>

#include "dream/run_status_t.hpp"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::view {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;

nlohmann::json ReplayOf(const std::string& log_path, size_t max_pose_values = kMaxPoseValues) {
  return nlohmann::json::parse(RunReplayJson(run_log::RunLog::Read(log_path), ViewSetup(), max_pose_values));
}

TEST(ReplayJsonTest, EveryStepsPosesForTheTimeline) {
  TempFolder folder;
  const nlohmann::json run = ReplayOf(SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 29).Write());
  EXPECT_EQ(run["type"], "run");
  EXPECT_EQ(run["num_robots"], 2);
  EXPECT_EQ(run["stride"], 1);
  ASSERT_EQ(run["steps"].size(), 30u);
  EXPECT_EQ(run["steps"][29], 29);
  ASSERT_EQ(run["poses"].size(), 30u);
  EXPECT_EQ(run["poses"][0].size(), 6u);  // x, y, theta of each robot
  EXPECT_DOUBLE_EQ(run["poses"][0][0].get<double>(), -1.0);
  ASSERT_EQ(run["velocities"].size(), 30u);
  EXPECT_EQ(run["velocities"][29], nlohmann::json::parse("[0,0,0,0]"));  // v, w of each robot
  EXPECT_TRUE(run["measured"].is_null());
  EXPECT_TRUE(run["violations"].empty());
  EXPECT_EQ(run["flaw"], "");
}

TEST(ReplayJsonTest, ViolationsLocatedAtTheirStepWithCountsSoFar) {
  TempFolder folder;
  SyntheticRunLog log(folder / "run.lcmlog");
  log.Obstacles(0, {dream::testing::Box(4, 1.0, 0.5, 0.2, 0.2)});
  log.Poses(0, {{0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}});
  log.Poses(1, {{0.0, 0.0, 0.0}, {0.1, 0.0, M_PI}});  // too close
  log.Poses(2, {{1.7, 0.0, 0.0}, {1.0, 0.5, 0.0}});   // outside; in the obstacle
  log.Poses(3, {{0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}});
  log.Status(3, run_status_t::FINISHED, {}, "reached the step limit");
  const nlohmann::json run = ReplayOf(log.Write());
  ASSERT_EQ(run["violations"].size(), 3u);
  EXPECT_EQ(run["violations"][0]["kind"], "collision");
  EXPECT_EQ(run["violations"][0]["step"], 1);
  EXPECT_EQ(run["violations"][1]["kind"], "boundary");
  EXPECT_EQ(run["violations"][1]["robot"], 0);
  EXPECT_DOUBLE_EQ(run["violations"][1]["x"].get<double>(), 1.7);
  EXPECT_EQ(run["violations"][2]["kind"], "obstacle");
  EXPECT_EQ(run["violations"][2]["other"], 4);
  // [step, boundary, collision, obstacle] so far, where they grow.
  EXPECT_EQ(run["counts"], nlohmann::json::parse("[[1,0,1,0],[2,1,1,1]]"));
  EXPECT_EQ(run["final"]["state"], run_status_t::FINISHED);
  EXPECT_EQ(run["obstacles"][0][0], 0);
  EXPECT_EQ(run["obstacles"][0][1][0][0], 4);
}

// The world validates a step's poses before it steps on, so the poses a run
// ended at are never judged: the replay's counts must be summary.json's.
TEST(ReplayJsonTest, ThePosesARunEndedAtAreNotJudgedAsTheWorldNeverJudgedThem) {
  TempFolder folder;
  SyntheticRunLog log(folder / "run.lcmlog");
  log.Poses(0, {{0.0, 0.0, 0.0}, {0.5, 0.0, 0.0}});
  log.Poses(1, {{1.7, 0.0, 0.0}, {0.5, 0.0, 0.0}});  // outside, judged before step 2
  log.Poses(2, {{1.8, 0.0, 0.0}, {0.5, 0.0, 0.0}});  // outside, where the run ended
  log.Status(2, run_status_t::FINISHED, {}, "reached the step limit");
  const nlohmann::json run = ReplayOf(log.Write());
  ASSERT_EQ(run["violations"].size(), 1u) << run["violations"].dump();
  EXPECT_EQ(run["violations"][0]["step"], 1);
  EXPECT_EQ(run["counts"], nlohmann::json::parse("[[1,1,0,0]]"));
  ASSERT_EQ(run["steps"].size(), 3u);  // the last poses are still drawn
}

TEST(ReplayJsonTest, MeasuredPosesOfARealisticRunBesideTheTrueOnes) {
  TempFolder folder;
  SyntheticRunLog log(folder / "run.lcmlog");
  log.Poses(0, {{0.0, 0.0, 0.0}});
  log.Poses(1, {{0.1, 0.0, 0.0}});
  robot_poses_t measured{};
  measured.step = 1;
  measured.utime = 33000;
  measured.num_robots = 1;
  measured.x = {0.12};
  measured.y = {-0.01};
  measured.theta = {0.02};
  measured.v = {0.0};
  measured.w = {0.0};
  log.MessageOn("DREAM_MEASURED_POSES", measured);  // what the agents were sent, with world.realism on
  const std::string path = log.Write();
  EXPECT_EQ(run_log::RunLog::Read(path).measured_poses().size(), 1u);
  const nlohmann::json run = ReplayOf(path);
  ASSERT_EQ(run["measured"].size(), 2u);
  EXPECT_TRUE(run["measured"][0].is_null());  // none at step 0
  EXPECT_EQ(run["measured"][1], nlohmann::json::parse("[0.12,-0.01,0.02]"));
  EXPECT_EQ(run["poses"][1], nlohmann::json::parse("[0.1,0,0]"));
}

TEST(ReplayJsonTest, ALongRunIsThinnedToItsBudget) {
  TempFolder folder;
  // 31 steps of 2 robots are 186 numbers; a budget of 60 keeps every 4th step.
  const nlohmann::json run = ReplayOf(SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 30).Write(), 60);
  EXPECT_EQ(run["stride"], 4);
  EXPECT_EQ(run["steps"], nlohmann::json::parse("[0,4,8,12,16,20,24,28,30]"));  // the last step is always there
  EXPECT_EQ(run["poses"].size(), 9u);
  EXPECT_EQ(run["t"].size(), 9u);
}

}  // namespace
}  // namespace dream::view
