#pragma once

#include <string>

namespace dream::sim {

/// Draws a run from its LCM log as a PNG: the arena to scale, each robot's
/// trajectory in its own colour from a hollow start marker to its final pose
/// (a disc of the robot's 0.11 m diameter with a heading tick), and the
/// virtual obstacles where they ended, with the paths of moving ones dashed.
/// Works on any log with DREAM_POSES: simulated or imported from the lab.
class TrajectoryPicture {
 public:
  /// Reads `log_path` and writes `png_path` atomically.
  /// @throws std::runtime_error naming the file when the log cannot be read,
  ///         holds no DREAM_POSES, or the PNG cannot be written.
  static void Render(const std::string& log_path, const std::string& png_path, int width_px = 1280);
};

}  // namespace dream::sim
