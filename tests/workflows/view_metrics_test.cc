// The view's metrics over time (KindStepMetrics, ViewReplay): computed by the
// run's kind step by step, they end on summary.json's metrics.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/bridge/metrics_json.h"
#include "dream/node/run_summary.h"
#include "dream/run_config/run_config.h"
#include "dream/run_log/run_log.h"
#include "dream/view/metric_timeline.h"
#include "dream/view/metrics_thread.h"
#include "dream/workflows/kind_step_metrics.h"
#include "dream/workflows/view_replay.h"
#include "../bridge/bridge_test_support.h"
#include "workflow_test_support.h"
#include "../support/source_tree.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;

const fs::path& RunFolder() {
  static const fs::path run = testing::SimulatedRun();
  return run;
}

nlohmann::json SummaryMetrics() {
  return nlohmann::json(node::RunSummary::Read((RunFolder() / "summary.json").string()).metrics);
}

TEST(ViewMetricsTest, TheKindsFiguresAfterTheLastStepAreSummaryJsons) {
  const run_config::RunConfig config = run_config::LoadRunConfigFile((RunFolder() / "config.yaml").string());
  const agent_host::ControllerFactory factory(config);
  const run_log::RunLog log = run_log::RunLog::Read((RunFolder() / "run.lcmlog").string());
  KindStepMetrics metrics(factory);
  const view::MetricTimeline timeline = view::MetricTimeline::OfRun(log, metrics);
  const nlohmann::json summary = SummaryMetrics();
  std::vector<std::string> compared;
  for (const view::MetricTimeline::Series& s : timeline.series()) {
    ASSERT_TRUE(summary.contains(s.name)) << s.name;
    ASSERT_TRUE(summary[s.name].is_number()) << s.name;
    EXPECT_EQ(s.points.back()[0], static_cast<double>(log.poses().back().step)) << s.name;
    EXPECT_EQ(s.points.back()[1], summary[s.name].get<double>()) << s.name;  // the same number, exactly
    compared.push_back(s.name);
  }
  // The kind's own figure and the safety figures every run has.
  EXPECT_NE(std::find(compared.begin(), compared.end(), "final_max_goal_error_m"), compared.end());
  EXPECT_NE(std::find(compared.begin(), compared.end(), "min_pairwise_distance_m"), compared.end());
  // Every one-number figure of summary.json that the kind computes is plotted.
  for (const auto& [name, value] : summary.items()) {
    if (value.is_number() && name != "goal") {
      EXPECT_NE(std::find(compared.begin(), compared.end(), name), compared.end()) << name;
    }
  }
}

TEST(ViewMetricsTest, TheGoalsToleranceAndTheCollisionDistanceAreThresholds) {
  const run_config::RunConfig config = run_config::LoadRunConfigFile((RunFolder() / "config.yaml").string());
  const agent_host::ControllerFactory factory(config);
  const run_log::RunLog log = run_log::RunLog::Read((RunFolder() / "run.lcmlog").string());
  KindStepMetrics metrics(factory);
  metrics.Observe(log.poses().front(), log.obstacles_at(0));
  std::vector<view::MetricReading> readings;
  metrics.Read(&readings);
  std::map<std::string, view::MetricReading> by_name;
  for (const view::MetricReading& r : readings) by_name[r.name] = r;
  ASSERT_TRUE(by_name.count("final_max_goal_error_m"));
  ASSERT_TRUE(by_name["final_max_goal_error_m"].threshold);
  EXPECT_EQ(*by_name["final_max_goal_error_m"].threshold, 0.05);  // the config's goal_tolerance_m
  EXPECT_EQ(by_name["final_max_goal_error_m"].threshold_label, "goal: within 0.05 m");
  ASSERT_TRUE(by_name["min_pairwise_distance_m"].threshold);
  EXPECT_EQ(*by_name["min_pairwise_distance_m"].threshold, 0.135);
  EXPECT_FALSE(by_name["near_miss_steps"].threshold);
}

TEST(ViewMetricsTest, TheReplayPlotsTheRunsMetricsEndingOnSummaryJsons) {
  const ViewReplay replay = ViewReplay::OfRun(RunFolder().string(), "", "");
  const nlohmann::json run = nlohmann::json::parse(replay.run_json);
  const nlohmann::json summary = SummaryMetrics();
  const nlohmann::json& series = run["metrics"]["series"];
  ASSERT_FALSE(series.empty());
  bool threshold_seen = false;
  for (const nlohmann::json& s : series) {
    const std::string name = s["name"];
    ASSERT_TRUE(summary.contains(name)) << name;
    EXPECT_EQ(s["steps"].back(), run["steps"].back()) << name;
    EXPECT_NEAR(s["values"].back().get<double>(), summary[name].get<double>(),
                1e-6 * std::max(1.0, std::abs(summary[name].get<double>())))
        << name;
    EXPECT_LE(s["steps"].size(), view::MetricTimeline::kMaxPoints);
    threshold_seen = threshold_seen || (name == "final_max_goal_error_m" && s.contains("threshold"));
  }
  EXPECT_TRUE(threshold_seen);
}

TEST(ViewMetricsTest, APythonControllersMetricsLiveEndOnWhatSummaryJsonSays) {
  // The Python twin of go_to_goal (the same eight robots) over the C++ run's steps: its metrics()
  // followed live as dream view follows them (KindStepMetrics on a MetricsThread, the class's
  // metrics() in a long-lived helper), against what summary.json is written from (MetricsJson).
  const std::string runtime = dream::testing::SourceDir() + "/python";
  const run_config::RunConfig config =
      run_config::LoadRunConfigFile(dream::testing::SourceDir() + "/config/go_to_goal_python.yaml");
  const agent_host::ControllerFactory factory(config);
  const run_log::RunLog log = run_log::RunLog::Read((RunFolder() / "run.lcmlog").string());
  ASSERT_EQ(log.num_robots(), config.num_robots);
  view::MetricsThread live([&] { return std::make_unique<KindStepMetrics>(factory, &config, runtime); });
  for (size_t i = 0; i < log.poses().size(); ++i) live.Offer(log.poses()[i], log.obstacles_at(i));
  ASSERT_TRUE(live.WaitUntilComputed(std::chrono::seconds(120)));  // the time-out only turns a hang into a failure
  ASSERT_FALSE(live.stopped());
  std::vector<view::MetricReading> readings;
  live.Read(&readings);
  const nlohmann::ordered_json summary = bridge::MetricsJson(config, factory, log, runtime);
  ASSERT_FALSE(summary.contains("error")) << summary["error"];
  std::map<std::string, view::MetricReading> by_name;
  for (const view::MetricReading& r : readings) by_name[r.name] = r;
  // The class's own figures (config/python/go_to_goal.py's metrics()), at the last step, exactly.
  for (const char* name : {"final_max_goal_error_m", "all_arrived_step"}) {
    ASSERT_TRUE(by_name.count(name)) << name;
    EXPECT_EQ(by_name[name].value, summary[name].get<double>()) << name;
    EXPECT_EQ(by_name[name].step, log.poses().back().step) << name;
  }
  EXPECT_EQ(by_name["min_pairwise_distance_m"].value, summary["min_pairwise_distance_m"].get<double>());
}

TEST(ViewMetricsTest, APythonHelperThatDiesEndsItsFiguresAndTheKindsOthersGoOn) {
  const fs::path folder = fs::path(bridge::testing::NewFolder("view_metrics_dying_helper"));
  std::ofstream(folder / "dying.py") << "import os\nfrom dream import Robot\n\nclass Dying(Robot):\n"
                                        "    @classmethod\n    def metrics(cls, run):\n        os._exit(3)\n";
  std::string text = "name: dying\nrobots: 8\nsteps: 300\ninitial_poses:\n";
  for (int i = 0; i < 8; ++i) text += "  - [" + std::to_string(-1.0 + 0.25 * i) + ", 0.0, 0.0]\n";
  text += "controller:\n  kind: python\n  module: dying.py\n  class: Dying\n";
  std::ofstream(folder / "dying.yaml") << text;
  const run_config::RunConfig config = run_config::LoadRunConfigFile((folder / "dying.yaml").string());
  const agent_host::ControllerFactory factory(config);
  const run_log::RunLog log = run_log::RunLog::Read((RunFolder() / "run.lcmlog").string());
  view::MetricsThread live(
      [&] { return std::make_unique<KindStepMetrics>(factory, &config, dream::testing::SourceDir() + "/python"); });
  for (size_t i = 0; i < log.poses().size(); ++i) live.Offer(log.poses()[i], log.obstacles_at(i));
  ASSERT_TRUE(live.WaitUntilComputed(std::chrono::seconds(120)));  // the time-out only turns a hang into a failure
  EXPECT_FALSE(live.stopped());                                    // the safety figures go on
  std::vector<view::MetricReading> readings;
  live.Read(&readings);
  std::map<std::string, double> by_name;
  for (const view::MetricReading& r : readings) by_name[r.name] = r.value;
  EXPECT_TRUE(by_name.count("min_pairwise_distance_m"));
}

}  // namespace
}  // namespace dream::workflows
