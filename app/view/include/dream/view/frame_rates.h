#pragma once

#include <algorithm>

namespace dream::view {

/// Frames a second the live view sends each browser, by how fast the run
/// goes (FramePacer measures it). Drawing a frame costs a browser about 7 ms
/// of CPU in software rendering, whatever is drawn (docs/performance.md#dream-view),
/// and on the run's own cores that time is taken from the run: a fast run,
/// which no one can follow step by step anyway, gets fewer frames.
struct FrameRates {
  int real_time = 30;  ///< up to FramePacer::kFastFactor x real time
  int fast = 10;       ///< faster than kFastFactor x real time
  int very_fast = 5;   ///< faster than kVeryFastFactor x real time: a progress display

  static constexpr int kMax = 60;  ///< a screen's refresh: more cannot be seen

  /// One rate whatever the run's speed (`dream view --fps`), clamped to 1..kMax.
  static FrameRates One(int frames_per_second) {
    const int fps = std::clamp(frames_per_second, 1, kMax);
    return {fps, fps, fps};
  }
};

}  // namespace dream::view
