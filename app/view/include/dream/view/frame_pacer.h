#pragma once

#include <chrono>
#include <cstdint>

namespace dream::view {

/// How long the live view's frame pump waits before its next frame: 1/fps
/// while the run goes at up to kFastFactor times real time, 1/fast_fps
/// beyond. A page cannot show a run at 20x real time step by step anyway, and
/// a browser drawing on the run's own cores slows a lockstep run by more than
/// its CPU time (docs/performance.md#dream-view), so a fast run gets fewer
/// frames. Give both rates the same to keep one rate.
class FramePacer {
 public:
  static constexpr double kFastFactor = 2.0;
  /// Wall time over which the run's speed is measured.
  static constexpr std::chrono::milliseconds kWindow{500};

  /// `step_s`: simulated seconds a step (the Robotarium's 0.033).
  FramePacer(int frames_per_second, int fast_frames_per_second, double step_s);

  /// The wait after a frame of `step` sent at `now`. A step lower than the
  /// last (a new run, a log played again) starts the measure over.
  std::chrono::microseconds Next(int64_t step, std::chrono::steady_clock::time_point now);

  /// Whether the last measure found the run faster than kFastFactor x real time.
  bool fast() const { return fast_; }

 private:
  std::chrono::microseconds period_;
  std::chrono::microseconds fast_period_;
  double step_s_;
  bool started_ = false;
  bool fast_ = false;
  int64_t window_step_ = 0;
  int64_t last_step_ = 0;
  std::chrono::steady_clock::time_point window_start_;
};

}  // namespace dream::view
