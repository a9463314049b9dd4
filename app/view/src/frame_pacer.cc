#include "dream/view/frame_pacer.h"

#include <algorithm>

namespace dream::view {
namespace {

std::chrono::microseconds PeriodOf(int frames_per_second) {
  return std::chrono::microseconds(1'000'000 / std::clamp(frames_per_second, 1, FrameRates::kMax));
}

}  // namespace

FramePacer::FramePacer(FrameRates rates, double step_s) : rates_(rates), step_s_(step_s) {}

std::chrono::microseconds FramePacer::Next(int64_t step, std::chrono::steady_clock::time_point now) {
  if (!started_ || step < last_step_) {
    started_ = true;
    speed_ = 0.0;
    window_step_ = step;
    window_start_ = now;
  }
  last_step_ = step;
  const std::chrono::duration<double> elapsed_s = now - window_start_;
  if (elapsed_s >= kWindow) {
    speed_ = static_cast<double>(step - window_step_) * step_s_ / elapsed_s.count();
    window_step_ = step;
    window_start_ = now;
  }
  return PeriodForSpeed();
}

std::chrono::microseconds FramePacer::PeriodForSpeed() const {
  if (speed_ > kVeryFastFactor) return PeriodOf(rates_.very_fast);
  if (speed_ > kFastFactor) return PeriodOf(rates_.fast);
  return PeriodOf(rates_.real_time);
}

}  // namespace dream::view
