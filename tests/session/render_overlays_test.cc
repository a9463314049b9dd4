// A Python controller's declared goals for pictures and the view: from a
// run's summary.json, or computed before a run by its class's goal_points().
#include "dream/session/render_overlays.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "dream/run_config/run_config.h"
#include "../support/scratch_folder.h"
#include "../support/source_tree.h"

namespace dream::session {
namespace {

namespace fs = std::filesystem;

class RenderOverlaysTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  run_config::RunConfig PairConfig(const std::string& goal_points_body) {
    Write("pair.py",
          "from dream import Robot\n\nclass Pair(Robot):\n    @classmethod\n"
          "    def goal_points(cls, config, num_robots):\n        " +
              goal_points_body + "\n");
    return run_config::LoadRunConfigFile(
        Write("pair.yaml",
              "name: pair\nrobots: 2\nsteps: 10\ninitial_poses:\n  - [-0.5, 0.0, 0.0]\n  - [0.5, 0.0, 0.0]\n"
              "controller:\n  kind: python\n  module: pair.py\n  class: Pair\n"));
  }

  dream::testing::ScratchFolder folder_{"dream_render_overlays"};
  const fs::path dir_ = folder_.path();
};

TEST_F(RenderOverlaysTest, DeclaredGoalsAreReadPerRobotAndMalformedPointsSkipped) {
  render::ArenaOverlays overlays;
  AddDeclaredGoals(nlohmann::json::parse(R"({"goal_points": [[[0.5, 0.25], [1, "x"]], [], "junk"]})"), &overlays);
  ASSERT_EQ(overlays.goals_m.size(), 3u);
  ASSERT_EQ(overlays.goals_m[0].size(), 1u);
  EXPECT_DOUBLE_EQ(overlays.goals_m[0][0][1], 0.25);
  EXPECT_TRUE(overlays.goals_m[1].empty());
  EXPECT_TRUE(overlays.goals_m[2].empty());
}

// summary.json is a file anyone may have edited: what it declares is bounded
// by what a run can have, not by the file.
TEST_F(RenderOverlaysTest, DeclaredGoalsStopAtTheRobotsARunCanHaveAndThePointsARobotMayDeclare) {
  nlohmann::json robots = nlohmann::json::array();
  for (size_t robot = 0; robot < kMaxGoalRobots + 5; ++robot) robots.push_back({{0.1, 0.2}});
  robots[0] = nlohmann::json::array();
  for (size_t point = 0; point < kMaxGoalPointsPerRobot + 7; ++point) robots[0].push_back({0.0, 0.0});
  render::ArenaOverlays overlays;
  AddDeclaredGoals(nlohmann::json{{"goal_points", robots}}, &overlays);
  ASSERT_EQ(overlays.goals_m.size(), kMaxGoalRobots);
  EXPECT_EQ(overlays.goals_m[0].size(), kMaxGoalPointsPerRobot);
  EXPECT_EQ(overlays.goals_m[1].size(), 1u);
}

TEST_F(RenderOverlaysTest, ASummaryJsonGivesItsGoalsAndAMissingOrMalformedOneNone) {
  render::ArenaOverlays overlays;
  EXPECT_FALSE(AddDeclaredGoalsOfRun((dir_ / "none.json").string(), &overlays));
  EXPECT_FALSE(AddDeclaredGoalsOfRun(Write("bad.json", "{\"metrics\": "), &overlays));
  EXPECT_FALSE(AddDeclaredGoalsOfRun(Write("no_points.json", R"({"metrics": {"kind": "python"}})"), &overlays));
  EXPECT_TRUE(overlays.goals_m.empty());
  EXPECT_TRUE(AddDeclaredGoalsOfRun(Write("summary.json", R"({"metrics": {"goal_points": [[[1, 2]]]}})"), &overlays));
  ASSERT_EQ(overlays.goals_m.size(), 1u);
  EXPECT_DOUBLE_EQ(overlays.goals_m[0][0][0], 1.0);
}

TEST_F(RenderOverlaysTest, APythonControllersGoalPointsAreComputedBeforeItsRun) {
  const run_config::RunConfig config = PairConfig("return [[(-0.25, 0.0)], [(0.25, 0.0), (0.25, 0.5)]]");
  render::ArenaOverlays overlays;
  AddKindGoals(config, dream::testing::SourceDir() + "/python", &overlays);
  ASSERT_EQ(overlays.goals_m.size(), 2u);
  ASSERT_EQ(overlays.goals_m[1].size(), 2u);
  EXPECT_DOUBLE_EQ(overlays.goals_m[1][1][1], 0.5);
  render::ArenaOverlays without_runtime;
  AddKindGoals(config, "", &without_runtime);
  EXPECT_TRUE(without_runtime.goals_m.empty());
}

TEST_F(RenderOverlaysTest, AGoalPointsThatFailsIsAnErrorNamingTheModule) {
  const run_config::RunConfig config = PairConfig("return [[(0.0, 0.0)]]");  // one list for two robots
  render::ArenaOverlays overlays;
  try {
    AddKindGoals(config, dream::testing::SourceDir() + "/python", &overlays);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("pair.py: Pair.goal_points(): expected one list of (x, y) per robot (2)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(overlays.goals_m.empty());
}

}  // namespace
}  // namespace dream::session
