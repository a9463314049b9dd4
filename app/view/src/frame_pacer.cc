#include "dream/view/frame_pacer.h"

#include <algorithm>

namespace dream::view {
namespace {

std::chrono::microseconds PeriodOf(int frames_per_second) {
  return std::chrono::microseconds(1'000'000 / std::max(frames_per_second, 1));
}

}  // namespace

FramePacer::FramePacer(int frames_per_second, int fast_frames_per_second, double step_s)
    : period_(PeriodOf(frames_per_second)), fast_period_(PeriodOf(fast_frames_per_second)), step_s_(step_s) {}

std::chrono::microseconds FramePacer::Next(int64_t step, std::chrono::steady_clock::time_point now) {
  if (!started_ || step < last_step_) {
    started_ = true;
    fast_ = false;
    window_step_ = step;
    window_start_ = now;
  }
  last_step_ = step;
  const std::chrono::duration<double> elapsed_s = now - window_start_;
  if (elapsed_s >= kWindow) {
    const double simulated_s = static_cast<double>(step - window_step_) * step_s_;
    fast_ = simulated_s > kFastFactor * elapsed_s.count();
    window_step_ = step;
    window_start_ = now;
  }
  return fast_ ? fast_period_ : period_;
}

}  // namespace dream::view
