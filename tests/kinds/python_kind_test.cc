// The python kind's hooks (ControllerKind::own_metrics, goals_before_run): a
// Python class's own metrics, goal and goal points, computed by a short-lived
// python3 from plain poses and the config, as the bridge and the session ask them.
#include "dream/python/kind.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "dream/run_config/run_config.h"
#include "../support/scratch_folder.h"
#include "../support/source_tree.h"

namespace dream::python {
namespace {

namespace fs = std::filesystem;

class PythonKindTest : public ::testing::Test {
 protected:
  // A two-robot run of the class `body` declares, in a module beside its config.
  run_config::RunConfig PairConfig(const std::string& body) {
    std::ofstream(dir_ / "pair.py") << "from dream import Robot\n\nclass Pair(Robot):\n" << body;
    std::ofstream(dir_ / "pair.yaml")
        << "name: pair\nrobots: 2\nsteps: 10\ninitial_poses:\n  - [-0.5, 0.0, 0.0]\n  - [0.5, 0.0, 0.0]\n"
           "controller:\n  kind: python\n  module: pair.py\n  class: Pair\n";
    return run_config::LoadRunConfigFile((dir_ / "pair.yaml").string());
  }

  // Three steps of two robots: robot 0 moves 0.1 m along x a step, robot 1 stays.
  static kind_api::RunPoses ThreeSteps() {
    kind_api::RunPoses poses;
    for (int64_t step = 0; step < 3; ++step) {
      poses.steps.push_back({step, {{-0.5 + 0.1 * static_cast<double>(step), 0.0, 0.0}, {0.5, 0.0, 0.0}}});
    }
    return poses;
  }

  const std::string runtime_ = dream::testing::SourceDir() + "/python";
  const kind_api::ControllerKind kind_ = Kind();
  dream::testing::ScratchFolder folder_{"dream_python_kind"};
  const fs::path dir_ = folder_.path();
};

constexpr const char* kMetricsAndGoal =
    "    @classmethod\n"
    "    def goal_points(cls, config, num_robots):\n"
    "        return [[(-0.2, 0.0)], [(0.5, 0.0), (0.5, 0.25)]]\n"
    "    @classmethod\n"
    "    def metrics(cls, run):\n"
    "        return {'final_x_m': float(run.positions()[-1, 0, 0]), 'x_m': run.positions()[:, 0, 0]}\n"
    "    @classmethod\n"
    "    def goal(cls, run, metrics):\n"
    "        return {'met': metrics['final_x_m'] > -0.35, 'completion_step': 2, 'detail': 'moved'}\n";

TEST_F(PythonKindTest, OwnMetricsAreTheClassesFiguresGoalAndGoalPointsOverThePoses) {
  ASSERT_TRUE(kind_.own_metrics);
  const nlohmann::json own = kind_.own_metrics(PairConfig(kMetricsAndGoal), ThreeSteps(), runtime_);
  EXPECT_NEAR(own["metrics"]["final_x_m"].get<double>(), -0.3, 1e-12);
  ASSERT_EQ(own["metrics"]["x_m"].size(), 3u);  // a series: [step, value] per step
  EXPECT_EQ(own["metrics"]["x_m"][2][0].get<int64_t>(), 2);
  EXPECT_NEAR(own["metrics"]["x_m"][2][1].get<double>(), -0.3, 1e-12);
  EXPECT_TRUE(own["goal"]["met"].get<bool>());
  EXPECT_EQ(own["goal"]["completion_step"].get<int64_t>(), 2);
  EXPECT_EQ(own["goal"]["detail"], "moved");
  EXPECT_EQ(own["goal_points"], nlohmann::json::parse("[[[-0.2, 0.0]], [[0.5, 0.0], [0.5, 0.25]]]"));
}

TEST_F(PythonKindTest, GoalsBeforeRunAreTheClassesGoalPointsPerRobot) {
  ASSERT_TRUE(kind_.goals_before_run);
  const auto goals = kind_.goals_before_run(PairConfig(kMetricsAndGoal), runtime_);
  ASSERT_EQ(goals.size(), 2u);
  ASSERT_EQ(goals[0].size(), 1u);
  EXPECT_DOUBLE_EQ(goals[0][0].x(), -0.2);
  ASSERT_EQ(goals[1].size(), 2u);
  EXPECT_DOUBLE_EQ(goals[1][1].y(), 0.25);
}

TEST_F(PythonKindTest, AClassThatDeclaresNothingGivesNoGoalsAndNoFigures) {
  const run_config::RunConfig config = PairConfig("    pass\n");
  EXPECT_TRUE(kind_.goals_before_run(config, runtime_).empty());
  const nlohmann::json own = kind_.own_metrics(config, ThreeSteps(), runtime_);
  EXPECT_TRUE(own["metrics"].empty());
  EXPECT_TRUE(own["goal"].is_null());
}

TEST_F(PythonKindTest, StepsWithDifferentRobotsAreRefusedNamingTheStep) {
  kind_api::RunPoses poses = ThreeSteps();
  poses.steps[1].poses.pop_back();
  try {
    kind_.own_metrics(PairConfig(kMetricsAndGoal), poses, runtime_);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "step 1 has 1 robots, the first 2");
  }
  EXPECT_THROW(kind_.own_metrics(PairConfig(kMetricsAndGoal), kind_api::RunPoses{}, runtime_), std::runtime_error);
}

TEST_F(PythonKindTest, AFailingFunctionIsAnErrorNamingTheModuleAndLine) {
  const run_config::RunConfig config = PairConfig(
      "    @classmethod\n"
      "    def metrics(cls, run):\n"
      "        raise ValueError('no figures today')\n");
  try {
    kind_.own_metrics(config, ThreeSteps(), runtime_);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("pair.py"), std::string::npos) << what;
    EXPECT_NE(what.find("no figures today"), std::string::npos) << what;
  }
}

TEST_F(PythonKindTest, AMissingRuntimeIsNamed) {
  try {
    kind_.goals_before_run(PairConfig(kMetricsAndGoal), (dir_ / "no_runtime").string());
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no_runtime/dream/run_metrics.py: missing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dream::python
