// The python kind's own_step_metrics (PythonStepMetrics): a Python class's
// metrics() followed while a run runs, by one long-lived helper, ending on the
// figures own_metrics gives for the same steps (summary.json's).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dream/python/kind.h"
#include "dream/python/python_step_metrics.h"
#include "dream/run_config/run_config.h"
#include "../support/scratch_folder.h"
#include "../support/source_tree.h"

namespace dream::python {
namespace {

namespace fs = std::filesystem;
using Figures = std::vector<kind_api::OwnStepMetrics::Figure>;

constexpr const char* kFigures =
    "    @classmethod\n"
    "    def metrics(cls, run):\n"
    "        d = run.positions()[:, 0, 0] - run.positions()[:, 1, 0]\n"
    "        return {'final_gap_m': float(abs(d[-1])), 'gap_m': abs(d), 'per_robot_x': run.poses[-1, :, 0],\n"
    "                'moved': bool(d[-1] != d[0]), 'mean_theta': float(run.poses[:, :, 2].mean())}\n";

class PythonStepMetricsTest : public ::testing::Test {
 protected:
  run_config::RunConfig PairConfig(const std::string& body) {
    std::ofstream(dir_ / "pair.py") << "import os\nfrom dream import Robot\n\nclass Pair(Robot):\n" << body;
    std::ofstream(dir_ / "pair.yaml")
        << "name: pair\nrobots: 2\nsteps: 10\ninitial_poses:\n  - [-0.5, 0.0, 0.0]\n  - [0.5, 0.0, 0.0]\n"
           "controller:\n  kind: python\n  module: pair.py\n  class: Pair\n";
    return run_config::LoadRunConfigFile((dir_ / "pair.yaml").string());
  }

  // `count` steps of two robots closing in, with numbers that do not round to short decimals.
  static kind_api::RunPoses Steps(int count) {
    kind_api::RunPoses poses;
    for (int64_t step = 0; step < count; ++step) {
      const double t = static_cast<double>(step) / 7.0;
      poses.steps.push_back({step, {{-0.5 + 0.001 * t, std::sin(t), t / 3.0}, {0.5 - 0.0007 * t, 0.1, -t}}});
    }
    return poses;
  }

  // Reads until the figures are of every step observed (the test's time-out only turns a hang into a failure).
  static int64_t ReadSettled(kind_api::OwnStepMetrics& metrics, Figures* figures) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    int64_t step = metrics.Read(figures);
    while (metrics.Pending() && std::chrono::steady_clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      step = metrics.Read(figures);
    }
    EXPECT_FALSE(metrics.Pending());
    return step;
  }

  const std::string runtime_ = dream::testing::SourceDir() + "/python";
  const kind_api::ControllerKind kind_ = Kind();
  dream::testing::ScratchFolder folder_{"dream_python_step_metrics"};
  const fs::path dir_ = folder_.path();
};

TEST_F(PythonStepMetricsTest, FollowedStepByStepTheLastFiguresAreOwnMetricsOfTheSameSteps) {
  ASSERT_TRUE(kind_.own_step_metrics);
  const run_config::RunConfig config = PairConfig(kFigures);
  const kind_api::RunPoses run = Steps(2000);
  const auto metrics = kind_.own_step_metrics(config, runtime_);
  Figures figures;
  int64_t newest = -1;
  for (const kind_api::RunPoses::Step& step : run.steps) {
    metrics->Observe(step);
    const int64_t at = metrics->Read(&figures);  // as the view's thread does: never waiting
    EXPECT_LE(at, step.step);
    EXPECT_GE(at, newest);  // the figures only move forward
    newest = at;
  }
  EXPECT_EQ(ReadSettled(*metrics, &figures), 1999);
  const nlohmann::json own = kind_.own_metrics(config, run, runtime_)["metrics"];
  std::map<std::string, double> by_name(figures.begin(), figures.end());
  // Numbers and each series' last value, exactly; flags and per-robot lists are no figure.
  ASSERT_EQ(by_name.size(), 3u);
  EXPECT_EQ(by_name.at("final_gap_m"), own["final_gap_m"].get<double>());
  EXPECT_EQ(by_name.at("mean_theta"), own["mean_theta"].get<double>());
  EXPECT_EQ(by_name.at("gap_m"), own["gap_m"].back()[1].get<double>());
  EXPECT_EQ(metrics->last_error(), "");
}

// The first answer waits for the helper's start-up: seconds on a loaded machine at the view's
// lowered priority. Counted as an evaluation's cost, it spaced the next asks three times that
// apart, past the end of a short run (view_metrics under load plotted one step).
TEST_F(PythonStepMetricsTest, TheHelpersStartUpDoesNotSpaceTheEvaluationsAfterIt) {
  const run_config::RunConfig config =
      PairConfig("    import time\n    time.sleep(1.0)  # a slow start-up\n" + std::string(kFigures));
  const kind_api::RunPoses run = Steps(3);
  const auto metrics = kind_.own_step_metrics(config, runtime_);
  const auto* python = dynamic_cast<const PythonStepMetrics*>(metrics.get());
  ASSERT_NE(python, nullptr);
  Figures figures;
  metrics->Observe(run.steps[0]);
  EXPECT_EQ(ReadSettled(*metrics, &figures), 0);  // after the second of start-up
  const auto answered_by = std::chrono::steady_clock::now();
  EXPECT_LE(python->next_ask(), answered_by + PythonStepMetrics::kMinInterval);
  metrics->Observe(run.steps[1]);
  EXPECT_EQ(ReadSettled(*metrics, &figures), 1);
  EXPECT_EQ(metrics->last_error(), "");
}

TEST_F(PythonStepMetricsTest, AFailureOnSomeStepsIsSaidAndTheLaterStepsAreStillComputed) {
  const run_config::RunConfig config = PairConfig(
      "    @classmethod\n"
      "    def metrics(cls, run):\n"
      "        if len(run.steps) < 50:\n"
      "            raise ValueError('too few steps yet')\n"
      "        return {'steps_seen': float(len(run.steps))}\n");
  const auto metrics = kind_.own_step_metrics(config, runtime_);
  Figures figures;
  const kind_api::RunPoses run = Steps(60);
  for (int i = 0; i < 10; ++i) metrics->Observe(run.steps[static_cast<size_t>(i)]);
  EXPECT_EQ(ReadSettled(*metrics, &figures), -1);  // nothing computed
  EXPECT_NE(metrics->last_error().find("too few steps yet"), std::string::npos) << metrics->last_error();
  EXPECT_NE(metrics->last_error().find("pair.py"), std::string::npos) << metrics->last_error();
  for (size_t i = 10; i < run.steps.size(); ++i) metrics->Observe(run.steps[i]);
  EXPECT_EQ(ReadSettled(*metrics, &figures), 59);
  ASSERT_EQ(figures.size(), 1u);
  EXPECT_EQ(figures[0].second, 60.0);
}

TEST_F(PythonStepMetricsTest, AHelperThatDiesIsAnErrorWithWhatItSaid) {
  const run_config::RunConfig config = PairConfig(
      "    @classmethod\n"
      "    def metrics(cls, run):\n"
      "        os.write(2, b'helper going away')\n"
      "        os._exit(3)\n");
  const auto metrics = kind_.own_step_metrics(config, runtime_);
  metrics->Observe(Steps(1).steps[0]);
  Figures figures;
  try {
    ReadSettled(*metrics, &figures);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("helper stopped"), std::string::npos) << what;
    EXPECT_NE(what.find("helper going away"), std::string::npos) << what;
  }
}

TEST_F(PythonStepMetricsTest, AStepOfOtherRobotsIsRefusedNamingIt) {
  const auto metrics = kind_.own_step_metrics(PairConfig(kFigures), runtime_);
  kind_api::RunPoses::Step step{4, {{0.0, 0.0, 0.0}}};
  try {
    metrics->Observe(step);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("step 4 has 1 robots, the run 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dream::python
