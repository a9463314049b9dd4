#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/view/step_metrics.h"

namespace dream::view {

/// A run's StepMetrics computed on a thread of their own, so the thread that
/// handles the bus (the world's own, under dream run --view) pays a copy per
/// step and never the kind's code: Offer() copies a step into a recycled
/// slot of a bounded queue and wakes nobody unless the thread sleeps with
/// nothing to do; the thread (at the view's lower priority) takes what
/// queued every kPollInterval, feeds it to the metrics, reads them and keeps
/// the readings for the frames. A queue that fills (the metrics kMaxQueuedSteps
/// behind the run) stops the plots of that run, said once, and never waits.
class MetricsThread {
 public:
  static constexpr size_t kMaxQueuedSteps = 4096;
  /// How long the thread gathers steps before it computes them, and how often
  /// it collects figures computed elsewhere (StepMetrics::Pending).
  static constexpr std::chrono::milliseconds kPollInterval{10};

  /// Starts the thread, which makes the metrics with `make` (the kind's code, off the bus's thread).
  explicit MetricsThread(std::function<std::unique_ptr<StepMetrics>()> make);
  /// Stops the thread (after the steps it is computing).
  ~MetricsThread();
  MetricsThread(const MetricsThread&) = delete;
  MetricsThread& operator=(const MetricsThread&) = delete;

  /// The run's next step (never a resend), from the bus's thread.
  void Offer(const robot_poses_t& poses, const obstacles_t& obstacles);
  /// The newest readings (none before the first step is computed, and none
  /// once the kind's code failed).
  void Read(std::vector<MetricReading>* readings) const;
  /// Changes each time the readings do.
  uint64_t version() const { return version_.load(); }
  /// Waits until every step offered is computed and nothing is pending, or
  /// the metrics stopped, or `timeout` passed; whether it got there.
  bool WaitUntilComputed(std::chrono::steady_clock::duration timeout);
  /// Whether the plots of this run stopped (the kind's code failed, or the queue filled).
  bool stopped() const;

 private:
  struct Slot {
    robot_poses_t poses{};
    obstacles_t obstacles{};
  };
  void Run(const std::function<std::unique_ptr<StepMetrics>()>& make);
  /// Waits for steps (or, when figures are pending, for the poll interval); the steps taken, into draining_.
  size_t TakeQueued(bool pending);
  void Publish(std::vector<MetricReading>* readings, size_t computed, bool pending);
  void Stop(const std::string& why);

  mutable std::mutex mutex_;
  std::condition_variable wake_;      // the thread: steps to take, or the end
  std::condition_variable computed_;  // WaitUntilComputed: the thread computed some
  std::vector<Slot> queued_;          // slots [0, queued_count_) hold steps
  size_t queued_count_ = 0;
  std::vector<Slot> draining_;  // the thread's: swapped with queued_, so slots are reused
  bool idle_ = false;           // the thread waits for steps with nothing pending
  bool overflowed_ = false;
  bool stopped_ = false;
  bool ending_ = false;
  bool pending_ = false;
  int64_t offered_ = 0;
  int64_t computed_count_ = 0;
  int64_t last_offered_step_ = -1;
  std::vector<MetricReading> readings_;
  std::atomic<uint64_t> version_{0};
  std::thread thread_;
};

}  // namespace dream::view
