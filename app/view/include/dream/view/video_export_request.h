#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "dream/render/viewport.h"
#include "dream/world/arena.h"

namespace dream::view {

/// What the page's "Export video" asks for, from the query of
/// /export/start: what the page shows (viewport, layers, steps) and how the
/// video is made. Every value is bounded: a query string is input from
/// anything that can reach the server. Maps one to one onto `dream render`'s
/// options (RenderArguments), so the page's export equals a command it prints.
struct VideoExportRequest {
  /// A parameter that is unknown, repeated, missing its pair or out of
  /// bounds; the message names the parameter and its value.
  struct Invalid : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
  };

  static constexpr int kMinWidthPx = 160;
  static constexpr int kMaxWidthPx = 1920;
  static constexpr double kMaxFps = 60.0;
  static constexpr double kMinSpeed = 0.01;
  static constexpr double kMaxSpeed = 10000.0;
  static constexpr double kMaxTrailS = 600.0;
  /// Frames of one video at most (20 minutes at 30 fps): a low speed on a
  /// long run is refused before any work, not drawn for hours.
  static constexpr int64_t kMaxFrames = 36000;

  bool gif = false;  ///< format=mp4 (default) or gif
  int width_px = 720;
  double fps = 30.0;
  double speed = 4.0;  ///< simulated seconds per video second
  double trail_s = 10.0;
  std::optional<render::Viewport> viewport;  ///< x0, y0, x1, y1 (all four or none)
  int64_t first_step = -1;                   ///< from, to (both or none): -1, the whole run
  int64_t last_step = -1;
  bool goals = true;
  bool violations = true;
  bool robot_ids = true;
  bool drawings = true;  ///< what the controllers drew (the page's drawings layer)
  bool radio_links = false;
  bool sensor_ranges = false;

  /// "format=mp4&width=720&fps=30&speed=4&trail=10&x0=-1&y0=-0.5&x1=0.5&y1=0.5&from=0&to=300&goals=1&..."
  /// Parameters left out keep their defaults (a GIF: 480 px, 15 fps).
  /// `arena` bounds the viewport; `run_first_step`..`run_last_step` the steps.
  /// @throws Invalid naming the parameter and its value.
  static VideoExportRequest Parse(std::string_view query, const world::Arena& arena, int64_t run_first_step,
                                  int64_t run_last_step);

  /// Frames the video has (RunAnimation's count, its end held a second) for
  /// the steps asked, or the run's `run_first_step`..`run_last_step`.
  int64_t FrameCount(int64_t run_first_step, int64_t run_last_step) const;
  /// `dream render` options giving this video, after `dream render RUN --out FILE`.
  std::vector<std::string> RenderArguments() const;
  /// "mp4" or "gif".
  std::string Extension() const { return gif ? "gif" : "mp4"; }
};

}  // namespace dream::view
