// MetricsThread: the run's metrics computed on a thread of their own, fed
// through a bounded queue by the bus's handler, which never waits on them;
// and BusFrameCollector's frames carrying what that thread computed.
#include "dream/view/metrics_thread.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <future>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "dream/lcm/lcm_bus.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/view/bus_frame_collector.h"

namespace dream::view {
namespace {

constexpr auto kGiveUp = std::chrono::seconds(60);  // only turns a hang into a failure

robot_poses_t Poses(int64_t run_id, int64_t step, double x) {
  robot_poses_t poses{};
  poses.run_id = run_id;
  poses.step = step;
  poses.num_robots = 1;
  poses.x = {x};
  poses.y = {0.0};
  poses.theta = {0.0};
  poses.v = {0.0};
  poses.w = {0.0};
  return poses;
}

/// The sum of robot 0's x over the steps observed, and the threads the metrics ran on.
class SumOfX final : public StepMetrics {
 public:
  struct Seen {
    std::mutex mutex;
    std::vector<std::thread::id> threads;
  };
  explicit SumOfX(Seen* seen, std::shared_future<void> go = {}, int64_t fail_at = -1)
      : seen_(seen), go_(std::move(go)), fail_at_(fail_at) {
    Note();
  }
  void Observe(const robot_poses_t& poses, const obstacles_t&) override {
    Note();
    if (go_.valid()) go_.wait();  // held, as a slow kind would be
    if (poses.step == fail_at_) throw std::runtime_error("no sum at this step");
    sum_ += poses.x[0];
    step_ = poses.step;
  }
  void Read(std::vector<MetricReading>* readings) override {
    readings->assign(1, MetricReading{"sum_x", sum_, std::nullopt, "", step_});
  }

 private:
  void Note() {
    std::lock_guard<std::mutex> lock(seen_->mutex);
    seen_->threads.push_back(std::this_thread::get_id());
  }
  Seen* seen_;
  std::shared_future<void> go_;
  int64_t fail_at_;
  double sum_ = 0.0;
  int64_t step_ = -1;
};

TEST(MetricsThreadTest, TheKindsCodeRunsOffTheOfferingThreadAndEndsOnEveryStep) {
  SumOfX::Seen seen;
  MetricsThread thread([&] { return std::make_unique<SumOfX>(&seen); });
  double expected = 0.0;
  for (int64_t step = 0; step < 1000; ++step) {
    thread.Offer(Poses(1, step, 0.001 * static_cast<double>(step)), obstacles_t{});
    expected += 0.001 * static_cast<double>(step);
  }
  ASSERT_TRUE(thread.WaitUntilComputed(kGiveUp));
  std::vector<MetricReading> readings;
  thread.Read(&readings);
  ASSERT_EQ(readings.size(), 1u);
  EXPECT_EQ(readings[0].value, expected);  // the same sum, in the same order
  EXPECT_EQ(readings[0].step, 999);
  std::lock_guard<std::mutex> lock(seen.mutex);
  ASSERT_EQ(seen.threads.size(), 1001u);  // made once, observed 1000 times
  for (const std::thread::id& id : seen.threads) EXPECT_NE(id, std::this_thread::get_id());
  EXPECT_FALSE(thread.stopped());
}

TEST(MetricsThreadTest, AFullQueueStopsThePlotsAndNeverWaits) {
  SumOfX::Seen seen;
  std::promise<void> go;
  MetricsThread thread([&] { return std::make_unique<SumOfX>(&seen, go.get_future().share()); });
  // The metrics are held in their first step: every offer past the queue's bound returns at once.
  for (int64_t step = 0; step < 3 * static_cast<int64_t>(MetricsThread::kMaxQueuedSteps); ++step) {
    thread.Offer(Poses(1, step, 1.0), obstacles_t{});
  }
  go.set_value();
  ASSERT_TRUE(thread.WaitUntilComputed(kGiveUp));
  EXPECT_TRUE(thread.stopped());
  std::vector<MetricReading> readings;
  thread.Read(&readings);
  EXPECT_TRUE(readings.empty());
}

TEST(MetricsThreadTest, TheKindsCodeThatThrowsEndsThePlotsOfTheRun) {
  SumOfX::Seen seen;
  MetricsThread thread([&] { return std::make_unique<SumOfX>(&seen, std::shared_future<void>(), 5); });
  for (int64_t step = 0; step < 10; ++step) thread.Offer(Poses(1, step, 1.0), obstacles_t{});
  ASSERT_TRUE(thread.WaitUntilComputed(kGiveUp));
  EXPECT_TRUE(thread.stopped());
  thread.Offer(Poses(1, 10, 1.0), obstacles_t{});  // taken and dropped
  std::vector<MetricReading> readings;
  thread.Read(&readings);
  EXPECT_TRUE(readings.empty());
}

TEST(MetricsThreadTest, AFrameCarriesWhatTheThreadComputedOnceItIsComputed) {
  lcm::LcmBus bus("memq://");
  BusFrameCollector collector(bus, world::WorldParams{});
  SumOfX::Seen seen;
  std::promise<void> go;
  std::shared_future<void> held = go.get_future().share();
  collector.FollowMetrics([&] { return std::make_unique<SumOfX>(&seen, held); });
  run_status_t status{};
  status.run_id = 7;
  status.state = run_status_t::RUNNING;
  status.num_robots = 1;
  lcm::Publish(bus, "DREAM_STATUS", status);
  lcm::Publish(bus, "DREAM_POSES", Poses(7, 0, 0.25));
  while (bus.HandleSubscriptions(0) > 0) {
  }
  // The step is drawn at once, its figures not yet: the kind's code is held on its thread.
  ViewFrame frame;
  uint64_t version = 0;
  ASSERT_TRUE(collector.TakeFrame(&frame, &version));
  EXPECT_EQ(frame.step, 0);
  EXPECT_TRUE(frame.metrics.empty());
  go.set_value();
  // Computed later: a new frame, with nothing new on the bus.
  const auto give_up = std::chrono::steady_clock::now() + kGiveUp;
  while (!collector.TakeFrame(&frame, &version) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(frame.metrics.size(), 1u);
  EXPECT_EQ(frame.metrics[0].value, 0.25);
  EXPECT_EQ(frame.metrics[0].step, 0);
}

}  // namespace
}  // namespace dream::view
