#include "dream/view/metrics_thread.h"

#include <spdlog/spdlog.h>

#include <exception>
#include <string>
#include <utility>

#include "dream/view/thread_priority.h"

namespace dream::view {

MetricsThread::MetricsThread(std::function<std::unique_ptr<StepMetrics>()> make) {
  thread_ = std::thread([this, make = std::move(make)] { Run(make); });
}

MetricsThread::~MetricsThread() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ending_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void MetricsThread::Offer(const robot_poses_t& poses, const obstacles_t& obstacles) {
  bool wake = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (stopped_ || overflowed_) return;
    if (queued_count_ == kMaxQueuedSteps) {
      overflowed_ = true;  // said by the thread: the bus's thread only sets a flag
      last_offered_step_ = poses.step;
      wake = true;
    } else {
      if (queued_count_ == queued_.size()) queued_.emplace_back();
      Slot& slot = queued_[queued_count_++];
      slot.poses = poses;  // copies into the slot's vectors: no allocation once they are big enough
      slot.obstacles = obstacles;
      ++offered_;
      last_offered_step_ = poses.step;
      wake = idle_ || queued_count_ == kMaxQueuedSteps / 2;
    }
  }
  if (wake) wake_.notify_one();
}

size_t MetricsThread::TakeQueued(bool pending) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (queued_count_ == 0 && !pending) {
    idle_ = true;
    wake_.wait(lock, [this] { return ending_ || overflowed_ || queued_count_ > 0; });
    idle_ = false;
  }
  // A batch: the steps of one interval (sooner when the queue is half full).
  wake_.wait_for(lock, kPollInterval,
                 [this] { return ending_ || overflowed_ || queued_count_ >= kMaxQueuedSteps / 2; });
  if (ending_) return 0;
  if (overflowed_) {
    lock.unlock();
    Stop("the view's metrics fell " + std::to_string(kMaxQueuedSteps) + " steps behind the run: plotted up to step " +
         std::to_string(last_offered_step_ - static_cast<int64_t>(kMaxQueuedSteps)) + " (a replay plots them all)");
    return 0;
  }
  std::swap(queued_, draining_);
  const size_t taken = queued_count_;
  queued_count_ = 0;
  return taken;
}

void MetricsThread::Run(const std::function<std::unique_ptr<StepMetrics>()>& make) {
  LowerThisThreadsPriority();
  std::unique_ptr<StepMetrics> metrics;
  try {
    metrics = make();
  } catch (const std::exception& e) {
    Stop(std::string("the run's metrics are not plotted: ") + e.what());
    return;
  }
  if (!metrics) return Stop("");
  std::vector<MetricReading> readings;
  bool pending = false;
  int64_t step = -1;
  for (;;) {
    const size_t taken = TakeQueued(pending);
    if (stopped()) return;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (ending_) return;
    }
    try {
      for (size_t i = 0; i < taken; ++i) {
        step = draining_[i].poses.step;
        metrics->Observe(draining_[i].poses, draining_[i].obstacles);
      }
      metrics->Read(&readings);
      pending = metrics->Pending();
    } catch (const std::exception& e) {
      // The kind's code: its plots stop, the run is still drawn.
      return Stop("the run's metrics stop at step " + std::to_string(step) + ": " + e.what());
    }
    Publish(&readings, taken, pending);
  }
}

void MetricsThread::Publish(std::vector<MetricReading>* readings, size_t computed, bool pending) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    readings_.swap(*readings);
    computed_count_ += static_cast<int64_t>(computed);
    pending_ = pending;
  }
  version_.fetch_add(1);
  computed_.notify_all();
}

void MetricsThread::Stop(const std::string& why) {
  if (!why.empty()) spdlog::warn("dream view: {}", why);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_ = true;
    readings_.clear();
  }
  version_.fetch_add(1);
  computed_.notify_all();
}

void MetricsThread::Read(std::vector<MetricReading>* readings) const {
  std::lock_guard<std::mutex> lock(mutex_);
  *readings = readings_;
}

bool MetricsThread::stopped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stopped_;
}

bool MetricsThread::WaitUntilComputed(std::chrono::steady_clock::duration timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  return computed_.wait_for(lock, timeout,
                            [this] { return stopped_ || (computed_count_ == offered_ && !pending_ && !overflowed_); });
}

}  // namespace dream::view
