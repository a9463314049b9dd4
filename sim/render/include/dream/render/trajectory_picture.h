#pragma once

#include <string>

#include "dream/render/arena_overlays.h"
#include "dream/render/render_format.h"
#include "dream/run_log/run_log.h"

namespace dream::render {

/// Draws a run as a picture: the arena to scale, each robot's trajectory in
/// its own colour from a hollow start marker to its final pose (a disc of the
/// robot's 0.11 m diameter with its id and a heading tick), the virtual
/// obstacles where they ended with the paths of moving ones dashed, and what
/// `overlays` adds (goals as crosses; sensor ranges and radio links at the
/// final poses when asked; each located violation as a red ring with a cross
/// and "k=<its first step>", with a second caption line counting them), with tick labels in metres round the arena, a
/// legend row (start, end, goal, obstacle) and a caption: the run's name and
/// verdict when `overlays` has them, the robots, steps and duration. Works on any log with DREAM_POSES: simulated or
/// imported from the lab.
class TrajectoryPicture {
 public:
  /// Writes the run of `log` as a PNG or SVG (`format`) to `path`, atomically.
  /// @throws std::runtime_error naming the file when the log holds no
  ///         DREAM_POSES (Drawable) or `path` cannot be written.
  static void Render(const run_log::RunLog& log, const ArenaOverlays& overlays, const std::string& path,
                     RenderFormat format, int width_px = 1280);

  /// The caption under the arena, e.g. "go_to_goal — clean (no errors or
  /// warnings) — 8 robots, steps 0..206 (6.8 s)".
  static std::string Caption(const run_log::RunLog& log, const ArenaOverlays& overlays);

  /// The second caption line of a run with violations (overlays.violations),
  /// e.g. "3 violations, the first at k=120 (summary.json violations_located)".
  static std::string ViolationCaption(const world::LocatedViolations& violations);
};

}  // namespace dream::render
