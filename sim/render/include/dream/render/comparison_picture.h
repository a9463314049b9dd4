#pragma once

#include <string>
#include <vector>

namespace dream::sim {

/// Draws two runs of one experiment over each other as a PNG, to compare a
/// simulated run with its lab run: each robot in its own colour, the first
/// run's trajectory dashed and thin (the plan), the second's solid (what
/// happened), both runs' final poses (hollow: first run, filled: second),
/// and caption lines under the arena (e.g. the tracking error).
class ComparisonPicture {
 public:
  /// Reads both logs and writes `png_path` atomically.
  /// @throws std::runtime_error naming the file when a log cannot be read or
  ///         holds no DREAM_POSES, or the PNG cannot be written.
  static void Render(const std::string& first_log, const std::string& second_log, const std::string& png_path,
                     const std::vector<std::string>& caption_lines, int width_px = 1280);
};

}  // namespace dream::sim
