// `sim_only: true`: a run declared for simulation only may have up to the
// bus's 128 robots; without it the config keeps the Robotarium simulator's 50.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "dream/config/controller_config.h"
#include "dream/run_config/run_config.h"

namespace dream::config {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// `robots` go_to_goal robots on a grid of ten columns 0.3 m apart and rows
// 0.2 m apart, centred, each with its goal 0.1 m ahead; `extra` is put on the
// line after `robots:` (line 4).
std::string GridConfig(int robots, const std::string& extra = "") {
  std::string poses;
  std::string goals;
  const int rows = (robots + 9) / 10;
  for (int i = 0; i < robots; ++i) {
    const double x = -1.35 + 0.3 * (i % 10);
    const double y = -0.1 * (rows - 1) + 0.2 * (i / 10);
    poses += "  - [" + std::to_string(x) + ", " + std::to_string(y) + ", 0.0]\n";
    goals += "    - [" + std::to_string(x + 0.1) + ", " + std::to_string(y) + "]\n";
  }
  return "name: grid\nseed: 1\nrobots: " + std::to_string(robots) + "\n" + extra + (extra.empty() ? "" : "\n") +
         "steps: 100\ninitial_poses:\n" + poses + "controller:\n  kind: go_to_goal\n  goals:\n" + goals;
}

run_config::RunConfig Load(const std::string& text) {
  return run_config::LoadRunConfig(ConfigNode::LoadString(text, "grid.yaml"));
}

std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SimOnlyConfigTest, FiftyRobotsNeedNoDeclaration) {
  const run_config::RunConfig config = Load(GridConfig(50));
  EXPECT_EQ(config.num_robots, 50);
  EXPECT_FALSE(config.sim_only);
  EXPECT_EQ(config.LabRefusal("export it"), "");
}

TEST(SimOnlyConfigTest, FiftyOneRobotsWithoutItAreRefusedSayingHowToLiftTheLimit) {
  const std::string error = ErrorOf(GridConfig(51));
  EXPECT_THAT(error, HasSubstr("grid.yaml:3: robots: must be at most 50 (the Robotarium simulator's limit; the lab "
                               "runs at most 20), got 51"));
  EXPECT_THAT(error, HasSubstr("add `sim_only: true` to run up to 128 robots in simulation only (it can never go to "
                               "the lab)"));
  // The same for an agent, which reads only the controller's part.
  try {
    LoadControllerConfig(ConfigNode::LoadString(GridConfig(51), "grid.yaml"));
    ADD_FAILURE() << "51 robots accepted without sim_only";
  } catch (const ConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("add `sim_only: true`"));
  }
  EXPECT_EQ(ErrorOf(GridConfig(51, "sim_only: false")), error);  // false is the default
}

TEST(SimOnlyConfigTest, AHundredRobotsLoadWithIt) {
  const run_config::RunConfig config = Load(GridConfig(100, "sim_only: true"));
  EXPECT_EQ(config.num_robots, 100);
  EXPECT_TRUE(config.sim_only);
  EXPECT_EQ(config.initial_poses.size(), 100u);
  EXPECT_EQ(LoadControllerConfig(ConfigNode::LoadString(GridConfig(100, "sim_only: true"), "grid.yaml")).num_robots,
            100);
  EXPECT_EQ(config.LabRefusal("export it"),
            "grid.yaml:4: sim_only: true — this run was declared simulation-only; remove `sim_only` (and use at "
            "most 20 robots) to export it");
  // A small run may be declared simulation-only too.
  EXPECT_TRUE(Load(GridConfig(3, "sim_only: true")).sim_only);
}

TEST(SimOnlyConfigTest, PastTheBusesBoundIsRefusedEitherWay) {
  EXPECT_THAT(ErrorOf(GridConfig(129, "sim_only: true")),
              HasSubstr("grid.yaml:3: robots: must be between 1 and 128 with sim_only (what one message of the bus "
                        "carries), got 129"));
  const std::string without = ErrorOf(GridConfig(129));
  EXPECT_THAT(without, HasSubstr("grid.yaml:3: robots: must be between 1 and 50"));
  EXPECT_THAT(without, HasSubstr("got 129"));
  EXPECT_THAT(without, Not(HasSubstr("add `sim_only: true`")));  // it would not help
  std::string none = GridConfig(1, "sim_only: true");
  none.replace(none.find("robots: 1\n"), 10, "robots: 0\n");
  EXPECT_THAT(ErrorOf(none), HasSubstr("grid.yaml:3: robots: must be between 1 and 128 with sim_only"));
}

TEST(SimOnlyConfigTest, StartPosesThatCannotBeGeneratedSayHowToPlaceThem) {
  // At 100 robots random placement 0.25 m apart runs out of room.
  std::string text = GridConfig(100, "sim_only: true");
  text.erase(text.find("initial_poses:\n"), text.find("controller:") - text.find("initial_poses:\n"));
  const std::string error = ErrorOf(text);
  EXPECT_THAT(error, HasSubstr("grid.yaml:1: initial_poses: cannot generate initial poses"));
  EXPECT_THAT(error, HasSubstr("100 robots"));
  EXPECT_THAT(error, HasSubstr("a smaller min_spacing_m"));
  EXPECT_THAT(error, HasSubstr("list one [x, y, theta] per robot under initial_poses"));
}

TEST(SimOnlyConfigTest, OnlyTrueOrFalseIsAccepted) {
  EXPECT_THAT(ErrorOf(GridConfig(2, "sim_only: \"yes\"")),
              HasSubstr("grid.yaml:4: sim_only: expected true or false, got the quoted text \"yes\""));
  EXPECT_THAT(ErrorOf(GridConfig(2, "sim_only: 1")), HasSubstr("grid.yaml:4: sim_only: expected true or false"));
  EXPECT_THAT(ErrorOf(GridConfig(2, "sim_only: [true]")), HasSubstr("grid.yaml:4: sim_only: expected true or false"));
  EXPECT_THAT(ErrorOf(GridConfig(2, "sim_onyl: true")), HasSubstr("did you mean 'sim_only'"));
}

}  // namespace
}  // namespace dream::config
