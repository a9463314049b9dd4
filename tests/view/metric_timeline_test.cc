#include "dream/view/metric_timeline.h"

#include <gtest/gtest.h>

#include <chrono>

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/view/bus_frame_collector.h"
#include "dream/view/frame_json.h"
#include "dream/view/replay_json.h"
#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::view {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;

/// Metrics a test can read: "x0" is robot 0's x at the step observed last,
/// "observed" how many steps were observed, "limited" has a threshold.
class RobotXMetrics final : public StepMetrics {
 public:
  explicit RobotXMetrics(int* observed_total = nullptr, int64_t throw_at_step = -1, bool read_throws = false)
      : observed_total_(observed_total), throw_at_step_(throw_at_step), read_throws_(read_throws) {}
  void Observe(const robot_poses_t& poses, const obstacles_t& obstacles) override {
    (void)obstacles;
    if (poses.step == throw_at_step_) throw std::runtime_error("the kind's metrics failed");
    x0_ = poses.x.empty() ? 0.0 : poses.x[0];
    ++observed_;
    if (observed_total_ != nullptr) ++*observed_total_;
  }
  void Read(std::vector<MetricReading>* readings) override {
    if (read_throws_) throw std::runtime_error("the kind's Write failed");
    readings->resize(3);
    (*readings)[0].name = "x0";
    (*readings)[0].value = x0_;
    (*readings)[1].name = "observed";
    (*readings)[1].value = observed_;
    (*readings)[2].name = "limited";
    (*readings)[2].value = 2.0 * x0_;
    (*readings)[2].threshold = 0.5;
    (*readings)[2].threshold_label = "goal: within 0.5";
  }

 private:
  int* observed_total_;
  int64_t throw_at_step_;
  bool read_throws_;
  double x0_ = 0.0;
  int observed_ = 0;
};

std::vector<MetricReading> One(const std::string& name, double value) {
  MetricReading reading;
  reading.name = name;
  reading.value = value;
  return {reading};
}

TEST(MetricTimelineTest, AShortRunKeepsEveryStep) {
  MetricTimeline timeline;
  for (int step = 0; step < 100; ++step) {
    ASSERT_TRUE(timeline.Due());
    timeline.Record(step, One("a", step * 0.5));
  }
  ASSERT_EQ(timeline.series().size(), 1u);
  EXPECT_EQ(timeline.series()[0].points.size(), 100u);
  EXPECT_EQ(timeline.series()[0].points[99][1], 49.5);
  EXPECT_EQ(timeline.stride(), 1);
}

TEST(MetricTimelineTest, ALongRunIsBoundedEvenlyWithoutReallocating) {
  MetricTimeline timeline;
  timeline.Record(0, One("a", 0.0));  // the series exists, its storage reserved
  const auto* storage = timeline.series()[0].points.data();
  (void)timeline.Due();
  for (int step = 1; step < 100000; ++step) {
    if (timeline.Due()) timeline.Record(step, One("a", step));
  }
  const auto& points = timeline.series()[0].points;
  EXPECT_LE(points.size(), MetricTimeline::kMaxPoints);
  EXPECT_GE(points.size(), MetricTimeline::kMaxPoints / 2);
  EXPECT_EQ(points.data(), storage);  // never reallocated
  EXPECT_EQ(points.front()[0], 0.0);  // the first step kept
  // Evenly spread: every gap is the stride.
  for (size_t i = 1; i < points.size(); ++i) ASSERT_EQ(points[i][0] - points[i - 1][0], timeline.stride()) << i;
  EXPECT_GT(points.back()[0], 100000 - 2 * timeline.stride());
}

TEST(MetricTimelineTest, SeriesAreBoundedInNumberAndTakeNoStepTwice) {
  MetricTimeline timeline;
  std::vector<MetricReading> many;
  for (size_t k = 0; k < MetricTimeline::kMaxSeries + 10; ++k) many.push_back(One("m" + std::to_string(k), 1.0)[0]);
  timeline.Record(3, many);
  timeline.Record(3, many);  // the same step again
  timeline.Record(2, many);  // an older one
  EXPECT_EQ(timeline.series().size(), MetricTimeline::kMaxSeries);
  EXPECT_EQ(timeline.series()[0].points.size(), 1u);
}

TEST(MetricTimelineTest, AWholeSeriesIsThinnedAndKeepsItsLastPoint) {
  MetricTimeline timeline;
  std::vector<std::array<double, 2>> points;
  for (int step = 0; step < 5000; ++step) points.push_back({double(step), step * 2.0});
  timeline.AddSeries("python_metric", points);
  timeline.AddSeries("python_metric", {{0.0, 1.0}});  // a second of the same name: ignored
  ASSERT_EQ(timeline.series().size(), 1u);
  const auto& kept = timeline.series()[0].points;
  EXPECT_LE(kept.size(), MetricTimeline::kMaxPoints);
  EXPECT_EQ(kept.back()[0], 4999.0);
  EXPECT_EQ(kept.back()[1], 9998.0);
}

TEST(MetricTimelineTest, ARunsTimelineEndsOnTheFiguresAfterItsLastStep) {
  TempFolder folder;
  const run_log::RunLog log = run_log::RunLog::Read(SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 2999).Write());
  RobotXMetrics metrics;
  const MetricTimeline timeline = MetricTimeline::OfRun(log, metrics);
  ASSERT_EQ(timeline.series().size(), 3u);
  for (const MetricTimeline::Series& s : timeline.series()) {
    EXPECT_LE(s.points.size(), MetricTimeline::kMaxPoints) << s.name;
    EXPECT_EQ(s.points.back()[0], 2999.0) << s.name;  // the last step, always
  }
  EXPECT_EQ(timeline.series()[1].points.back()[1], 3000.0);  // every step observed, once
  EXPECT_EQ(timeline.series()[0].points.back()[1], log.poses().back().x[0]);
  EXPECT_EQ(timeline.series()[2].threshold, 0.5);
  EXPECT_EQ(timeline.series()[2].threshold_label, "goal: within 0.5");
}

TEST(MetricTimelineTest, TheReplayCarriesTheSeriesAndTheirThresholds) {
  TempFolder folder;
  const run_log::RunLog log = run_log::RunLog::Read(SyntheticRunLog::TwoRobots(folder / "run.lcmlog", 29).Write());
  RobotXMetrics metrics;
  const MetricTimeline timeline = MetricTimeline::OfRun(log, metrics);
  const nlohmann::json run = nlohmann::json::parse(RunReplayJson(log, ViewSetup(), kMaxPoseValues, &timeline));
  ASSERT_EQ(run["metrics"]["series"].size(), 3u);
  const nlohmann::json& limited = run["metrics"]["series"][2];
  EXPECT_EQ(limited["name"], "limited");
  EXPECT_EQ(limited["steps"].size(), 30u);
  EXPECT_EQ(limited["steps"][29], 29);
  EXPECT_NEAR(limited["values"][29].get<double>(), 2.0 * log.poses().back().x[0], 1e-6);
  EXPECT_EQ(limited["threshold"], 0.5);
  EXPECT_EQ(limited["label"], "goal: within 0.5");
  // Without metrics: an empty list, never a missing key.
  const nlohmann::json bare = nlohmann::json::parse(RunReplayJson(log, ViewSetup()));
  EXPECT_TRUE(bare["metrics"]["series"].empty());
}

robot_poses_t PosesAt(int64_t run_id, int64_t step, double x0) {
  robot_poses_t poses{};
  poses.run_id = run_id;
  poses.step = step;
  poses.num_robots = 1;
  poses.x = {x0};
  poses.y = {0.0};
  poses.theta = {0.0};
  poses.v = {0.0};
  poses.w = {0.0};
  return poses;
}

void Step(lcm::LcmBus& bus, int64_t run_id, int64_t step, double x0) {
  run_status_t status{};
  status.run_id = run_id;
  status.step = step;
  status.state = run_status_t::RUNNING;
  status.num_robots = 1;
  obstacles_t obstacles{};
  obstacles.run_id = run_id;
  obstacles.step = step;
  lcm::Publish(bus, "DREAM_OBSTACLES", obstacles);
  lcm::Publish(bus, "DREAM_STATUS", status);
  lcm::Publish(bus, "DREAM_POSES", PosesAt(run_id, step, x0));
  while (bus.HandleSubscriptions(0) > 0) {
  }
}

constexpr auto kGiveUp = std::chrono::seconds(60);  // only turns a hang into a failure

class LiveMetricsTest : public ::testing::Test {
 protected:
  lcm::LcmBus bus_{"memq://"};
  BusFrameCollector collector_{bus_, world::WorldParams()};
  uint64_t version_ = 0;
  ViewFrame frame_;
  int made_ = 0;
  int observed_ = 0;
};

TEST_F(LiveMetricsTest, EachStepIsObservedOnceAndEachFrameCarriesTheFigures) {
  collector_.FollowMetrics([this] {
    ++made_;
    return std::make_unique<RobotXMetrics>(&observed_);
  });
  for (int64_t step = 0; step < 4; ++step) Step(bus_, 9, step, 0.1 * static_cast<double>(step));
  Step(bus_, 9, 3, 0.3);                            // a resend: the same step, not observed again
  ASSERT_TRUE(collector_.WaitForMetrics(kGiveUp));  // computed on the metrics' own thread
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  ASSERT_EQ(frame_.metrics.size(), 3u);
  EXPECT_EQ(frame_.metrics[0].name, "x0");
  EXPECT_DOUBLE_EQ(frame_.metrics[0].value, 0.3);
  EXPECT_EQ(frame_.metrics[1].value, 4.0);
  EXPECT_EQ(observed_, 4);
  const nlohmann::json json = nlohmann::json::parse(FrameJson(frame_));
  ASSERT_EQ(json["metrics"].size(), 3u);
  EXPECT_EQ(json["metrics"][2]["name"], "limited");
  EXPECT_EQ(json["metrics"][2]["threshold"], 0.5);
  EXPECT_EQ(json["metrics"][2]["label"], "goal: within 0.5");
  EXPECT_FALSE(json["metrics"][0].contains("threshold"));
}

TEST_F(LiveMetricsTest, ARunDrawnAfreshGetsMetricsOfItsOwn) {
  collector_.FollowMetrics([this] {
    ++made_;
    return std::make_unique<RobotXMetrics>(&observed_);
  });
  Step(bus_, 9, 0, 0.0);
  Step(bus_, 9, 0, 0.0);  // a resend
  Step(bus_, 9, 1, 0.1);
  run_status_t finished{};
  finished.run_id = 9;
  finished.step = 1;
  finished.state = run_status_t::FINISHED;
  lcm::Publish(bus_, "DREAM_STATUS", finished);
  Step(bus_, 10, 0, 1.0);  // a new run
  ASSERT_TRUE(collector_.WaitForMetrics(kGiveUp));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.run_id, 10);
  // One when asked (each made on a thread of its own, joined when the next run starts), then one per run drawn.
  EXPECT_EQ(made_, 3);
  EXPECT_EQ(frame_.metrics[1].value, 1.0);  // run 10's only step
}

TEST_F(LiveMetricsTest, MetricsThatThrowStopButTheRunIsStillDrawn) {
  collector_.FollowMetrics([] { return std::make_unique<RobotXMetrics>(nullptr, 2); });
  for (int64_t step = 0; step < 4; ++step) Step(bus_, 9, step, 0.1 * static_cast<double>(step));
  ASSERT_TRUE(collector_.WaitForMetrics(kGiveUp));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.step, 3);
  EXPECT_TRUE(frame_.metrics.empty());
  EXPECT_EQ(nlohmann::json::parse(FrameJson(frame_))["metrics"], nlohmann::json::array());
}

TEST_F(LiveMetricsTest, MetricsWhoseReadingThrowsStopAndTheFrameIsStillTaken) {
  collector_.FollowMetrics([] { return std::make_unique<RobotXMetrics>(nullptr, -1, true); });
  Step(bus_, 9, 0, 0.0);
  ASSERT_TRUE(collector_.WaitForMetrics(kGiveUp));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_EQ(frame_.step, 0);
  EXPECT_TRUE(frame_.metrics.empty());
  Step(bus_, 9, 1, 0.1);
  ASSERT_TRUE(collector_.WaitForMetrics(kGiveUp));
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));  // no second attempt: they stopped
  EXPECT_TRUE(frame_.metrics.empty());
}

TEST_F(LiveMetricsTest, WithoutMetricsFramesCarryNone) {
  Step(bus_, 9, 0, 0.0);
  ASSERT_TRUE(collector_.TakeFrame(&frame_, &version_));
  EXPECT_TRUE(frame_.metrics.empty());
}

}  // namespace
}  // namespace dream::view
