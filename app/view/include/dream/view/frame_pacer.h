#pragma once

#include <chrono>
#include <cstdint>

#include "dream/view/frame_rates.h"

namespace dream::view {

/// How long the live view's frame pump waits before its next frame: the
/// FrameRates' rate for the run's speed, measured over kWindow of wall time.
/// A page cannot show a run at 20x real time step by step anyway, and a
/// browser drawing on the run's own cores slows a lockstep run by more than
/// its CPU time (docs/performance.md#dream-view), so a fast run gets fewer
/// frames.
class FramePacer {
 public:
  static constexpr double kFastFactor = 2.0;
  static constexpr double kVeryFastFactor = 10.0;
  /// Wall time over which the run's speed is measured.
  static constexpr std::chrono::milliseconds kWindow{500};

  /// `step_s`: simulated seconds a step (the Robotarium's 0.033). Rates are
  /// clamped to 1..FrameRates::kMax.
  FramePacer(FrameRates rates, double step_s);

  /// The wait after a frame of `step` sent at `now`. A step lower than the
  /// last (a new run, a log played again) starts the measure over.
  std::chrono::microseconds Next(int64_t step, std::chrono::steady_clock::time_point now);

  /// The last measure of the run's speed, in times real time (0 until measured).
  double speed() const { return speed_; }

 private:
  std::chrono::microseconds PeriodForSpeed() const;

  FrameRates rates_;
  double step_s_;
  bool started_ = false;
  double speed_ = 0.0;
  int64_t window_step_ = 0;
  int64_t last_step_ = 0;
  std::chrono::steady_clock::time_point window_start_;
};

}  // namespace dream::view
