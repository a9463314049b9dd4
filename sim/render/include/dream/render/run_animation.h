#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "dream/render/arena_layout.h"
#include "dream/render/arena_overlays.h"
#include "dream/render/render_format.h"
#include "dream/render/viewport.h"
#include "dream/run_log/run_log.h"

namespace dream::render {

/// How a run becomes a video.
struct AnimationOptions {
  int width_px = 720;       ///< frame width (rounded down to even); the height follows the arena
  double fps = 30.0;        ///< video frames per second, 1..120
  double speed = 4.0;       ///< simulated seconds per video second (> 0): 3,000 steps = 99 s play in ~25 s
  double trail_s = 10.0;    ///< simulated seconds of path drawn behind each robot (0: none)
  double hold_end_s = 1.0;  ///< the last frame stays this long, video seconds (>= 0)
  /// The part of the world shown (zoom and pan: ArenaLayout); none: the arena.
  std::optional<Viewport> viewport;
  /// The steps shown, first to last (both in the log's range); -1: the log's first, last.
  int64_t first_step = -1;
  int64_t last_step = -1;
  bool robot_ids = true;  ///< each robot's id on its disc
};

/// A run as a video, like the thesis's videos: the arena to scale, robots as
/// discs of their 0.11 m diameter with ids and headings, trails, obstacles
/// where they are at each moment (moving ones with their faint path), goals,
/// and optionally sensor ranges and radio links (ArenaOverlays), each located
/// violation (ArenaOverlays::violations) from its first step on as a red ring
/// with "k=<its first step>" (faded once over) and a caption line counting
/// those begun so far, tick labels
/// in metres, a legend row, and a caption: the run's name and verdict when
/// known, then the step and time. Frame f shows simulated time min(f * speed / fps,
/// duration) after the first step shown, so there are ceil(duration * fps / speed) + 1
/// frames of the run (duration: from the first to the last step shown) plus
/// round(hold_end_s * fps) of the last one.
class RunAnimation {
 public:
  /// `log` and `overlays` must outlive the animation.
  /// @throws std::invalid_argument naming the option when one is out of range,
  ///         std::runtime_error when the log holds no DREAM_POSES (Drawable).
  RunAnimation(const run_log::RunLog& log, const ArenaOverlays& overlays, AnimationOptions options);
  ~RunAnimation();
  RunAnimation(const RunAnimation&) = delete;
  RunAnimation& operator=(const RunAnimation&) = delete;

  int frame_count() const { return frame_count_; }
  double fps() const { return options_.fps; }
  /// frame_count() / fps(), seconds.
  double duration_s() const { return frame_count_ / options_.fps; }
  const ArenaLayout& layout() const { return layout_; }
  /// The simulation step frame `frame` shows.
  int64_t StepOfFrame(int frame) const;

  /// Draws frame `frame` into the frame buffer (pixels(), stride_bytes()).
  void DrawFrame(int frame);
  /// The frame buffer: cairo RGB24 (native-endian xRGB words).
  const unsigned char* pixels() const;
  int stride_bytes() const;
  /// Draws frame `frame` and writes it as a PNG, atomically (previews, tests).
  void WriteFramePng(int frame, const std::string& png_path);

  /// Encodes every frame to `path` (kMp4: H.264; kGif: two passes, a palette
  /// from a sample of frames, then the frames) with ffmpeg into a temporary
  /// file beside `path`, renamed into place when complete.
  /// `progress` is told the frames drawn so far and how many there are to
  /// draw (a GIF's palette pass counts too), after each frame.
  /// @return false, leaving nothing behind, when `cancelled` said so.
  /// @throws std::runtime_error naming the path, or quoting ffmpeg.
  using Progress = std::function<void(int drawn, int total)>;
  bool Write(const std::string& path, RenderFormat format, const std::function<bool()>& cancelled = {},
             const Progress& progress = {});
  /// Frames Write draws for `format`: frame_count(), plus the palette's sample for a GIF.
  int FramesToDraw(RenderFormat format) const;

 private:
  struct Surfaces;
  void DrawStaticLayer();
  /// The second caption line when the run has violations: how many began by `step`.
  std::string ViolationsSoFar(int64_t step) const;
  bool Encode(const std::string& path, RenderFormat format, const std::function<bool()>& cancelled,
              const Progress& progress);

  const run_log::RunLog& log_;
  const ArenaOverlays& overlays_;
  AnimationOptions options_;
  ArenaLayout layout_;
  bool obstacles_move_;
  int64_t first_step_;
  int64_t last_step_;
  int64_t trail_steps_;
  int64_t radio_window_steps_;
  int frame_count_ = 0;
  std::string run_label_;  // "name — verdict — " before each frame's caption (RunLabel)
  std::unique_ptr<Surfaces> surfaces_;
};

}  // namespace dream::render
