#pragma once

#include <string>
#include <vector>

#include "dream/run_log/run_log.h"

namespace dream::render {

/// Draws two runs of one experiment over each other as a PNG, to compare a
/// simulated run with its lab run: each robot in its own colour, the first
/// run's trajectory dashed and thin (the plan), the second's solid (what
/// happened), the second run's start poses (small hollow discs), both runs'
/// final poses (hollow: first run, filled with the robot's id: second), and
/// caption lines under the arena (e.g. the tracking error of robot 7).
class ComparisonPicture {
 public:
  /// Writes the two runs to `png_path` atomically.
  /// @throws std::runtime_error naming the file when a log holds no
  ///         DREAM_POSES (Drawable) or the PNG cannot be written.
  static void Render(const run_log::RunLog& first, const run_log::RunLog& second, const std::string& png_path,
                     const std::vector<std::string>& caption_lines, int width_px = 1280);
};

}  // namespace dream::render
