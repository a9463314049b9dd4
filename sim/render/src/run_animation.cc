#include "dream/render/run_animation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "arena_painter.h"
#include "dream/files/temporary_file.h"
#include "dream/render/ffmpeg_encoder.h"
#include "dream/render/run_geometry.h"
#include "dream/robotarium/robotarium_constants.h"
#include "picture_surface.h"
#include "range_sprites.h"
#include "violation_painter.h"

namespace dream::render {
namespace {

constexpr double kStepS = robotarium::RobotariumConstants::kTimeStepSeconds;
constexpr double kRadioFlashS = 0.5;      // a broadcast's lines fade out over this much simulated time
constexpr int kPaletteSampleFrames = 40;  // GIF: frames the palette is computed from

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

void CheckOption(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// H.264 in yuv420p needs even frame sizes.
int EvenFrameWidth(int width_px) {
  CheckOption(width_px >= ArenaLayout::kMinWidthPx && width_px <= ArenaLayout::kMaxWidthPx,
              "--width must be " + std::to_string(ArenaLayout::kMinWidthPx) + ".." +
                  std::to_string(ArenaLayout::kMaxWidthPx) + " px, got " + std::to_string(width_px));
  return width_px - width_px % 2;
}

// A viewport's world reaches past the frame: nothing drawn there.
void ClipToFrame(cairo_t* cr, const ArenaLayout& layout) {
  if (!layout.zoomed()) return;
  cairo_rectangle(cr, layout.frame_left_px(), layout.frame_top_px(), layout.frame_right_px() - layout.frame_left_px(),
                  layout.frame_bottom_px() - layout.frame_top_px());
  cairo_clip(cr);
}

// The step range shown, checked against the log's.
int64_t CheckedStep(int64_t step, int64_t fallback, const run_log::RunLog& log, const char* which) {
  if (step < 0) return fallback;
  if (step < log.first_step() || step > log.last_step()) {
    throw std::invalid_argument(std::string("--steps: the ") + which + " step " + std::to_string(step) +
                                " is not in the run (steps " + std::to_string(log.first_step()) + "-" +
                                std::to_string(log.last_step()) + ")");
  }
  return step;
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", value);
  return text;
}

}  // namespace

// The static layer (background, goals, obstacles that never move) is drawn
// once; each frame starts as a copy of it.
struct RunAnimation::Surfaces {
  explicit Surfaces(const ArenaLayout& layout) : range_sprites(layout) {}
  RangeSprites range_sprites;
  SurfacePtr background{nullptr, cairo_surface_destroy};
  SurfacePtr frame{nullptr, cairo_surface_destroy};
  ContextPtr frame_cr{nullptr, cairo_destroy};
};

RunAnimation::RunAnimation(const run_log::RunLog& log, const ArenaOverlays& overlays, AnimationOptions options)
    : log_(Drawable(log)),
      overlays_(overlays),
      options_(options),
      layout_(EvenFrameWidth(options.width_px), overlays.violations.total() > 0 ? 2 : 1, /*even_size=*/true,
              options.viewport),
      obstacles_move_(!MovingObstaclePaths(log).empty()),
      first_step_(CheckedStep(options.first_step, log.first_step(), log, "first")),
      last_step_(CheckedStep(options.last_step, log.last_step(), log, "last")),
      surfaces_(std::make_unique<Surfaces>(layout_)) {
  CheckOption(first_step_ <= last_step_, "--steps: the first step " + std::to_string(first_step_) +
                                             " is after the last " + std::to_string(last_step_));
  CheckOption(std::isfinite(options.fps) && options.fps >= 1 && options.fps <= 120,
              "--fps must be 1..120, got " + Number(options.fps));
  CheckOption(std::isfinite(options.speed) && options.speed > 0 && options.speed <= 10000,
              "--speed must be > 0 (simulated seconds per video second), got " + Number(options.speed));
  CheckOption(std::isfinite(options.trail_s) && options.trail_s >= 0,
              "--trail must be >= 0 s, got " + Number(options.trail_s));
  CheckOption(std::isfinite(options.hold_end_s) && options.hold_end_s >= 0 && options.hold_end_s <= 60,
              "the end hold must be 0..60 s, got " + Number(options.hold_end_s));
  trail_steps_ = std::llround(options.trail_s / kStepS);
  radio_window_steps_ = std::max<int64_t>(std::llround(kRadioFlashS / kStepS),
                                          std::llround(std::ceil(options.speed / options.fps / kStepS)));
  const double shown_s = static_cast<double>(last_step_ - first_step_) * kStepS;
  const int run_frames = static_cast<int>(std::ceil(shown_s * options.fps / options.speed - 1e-9)) + 1;
  frame_count_ = run_frames + static_cast<int>(std::lround(options.hold_end_s * options.fps));
  run_label_ = RunLabel(overlays, /*short_verdict=*/true);
  DrawStaticLayer();
}

RunAnimation::~RunAnimation() = default;

void RunAnimation::DrawStaticLayer() {
  const int width = layout_.width_px();
  const int height = layout_.height_px();
  surfaces_->background.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  {
    const ContextPtr cr(cairo_create(surfaces_->background.get()), cairo_destroy);
    const ArenaPainter painter(cr.get(), layout_);
    painter.Background();
    const std::vector<std::vector<std::array<double, 2>>> moving = MovingObstaclePaths(log_);
    cairo_save(cr.get());
    ClipToFrame(cr.get(), layout_);
    painter.ObstaclePaths(moving);
    if (!obstacles_move_) painter.Obstacles(log_.obstacles_at(log_.poses().size() - 1).obstacles);
    painter.Goals(overlays_.goals_m);
    cairo_restore(cr.get());
    using Item = ArenaPainter::LegendItem;
    std::vector<Item> legend = {{Item::Marker::kRobot, "robot", ArenaPainter::RobotLook::kFilled, 1.0}};
    if (!overlays_.goals_m.empty()) legend.push_back({Item::Marker::kGoal, "goal"});
    bool obstacles = !moving.empty();
    for (size_t i = 0; i < log_.poses().size() && !obstacles; ++i) obstacles = !log_.obstacles_at(i).obstacles.empty();
    if (obstacles) legend.push_back({Item::Marker::kObstacle, "obstacle"});
    if (overlays_.violations.total() > 0)
      legend.push_back({Item::Marker::kViolation, "violation (k = its first step)"});
    painter.Legend(legend);
  }
  surfaces_->frame.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height));
  surfaces_->frame_cr.reset(cairo_create(surfaces_->frame.get()));
}

int64_t RunAnimation::StepOfFrame(int frame) const {
  const double t = frame * options_.speed / options_.fps;
  return std::min<int64_t>(first_step_ + std::llround(t / kStepS), last_step_);
}

void RunAnimation::DrawFrame(int frame) {
  cairo_t* cr = surfaces_->frame_cr.get();
  cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
  cairo_set_source_surface(cr, surfaces_->background.get(), 0, 0);
  cairo_paint(cr);
  cairo_set_operator(cr, CAIRO_OPERATOR_OVER);

  const ArenaPainter painter(cr, layout_);
  const int64_t step = StepOfFrame(frame);
  const size_t now = log_.PoseIndexAtStep(step);
  const robot_poses_t& poses = log_.poses()[now];
  cairo_save(cr);
  ClipToFrame(cr, layout_);
  if (obstacles_move_) painter.Obstacles(log_.obstacles_at(now).obstacles);
  surfaces_->range_sprites.Draw(cr, overlays_, poses);
  if (trail_steps_ > 0) {
    const size_t from = log_.PoseIndexAtStep(step - trail_steps_);
    for (int32_t i = 0; i < poses.num_robots; ++i) painter.Track(i, RobotPath(log_, i, from, now), 2.0, 0.6);
  }
  painter.RadioLinks(overlays_, log_, now, radio_window_steps_);
  painter.Drawings(overlays_, log_, poses.step);
  for (int32_t i = 0; i < poses.num_robots; ++i) {
    const auto k = static_cast<size_t>(i);
    painter.Robot(i, poses.x[k], poses.y[k], poses.theta[k], ArenaPainter::RobotLook::kFilled, options_.robot_ids);
  }
  // Each violation from its first step on, where it happened; faded once it is over.
  ViolationPainter(cr, layout_).Mark(overlays_.violations.listed, poses.step);
  cairo_restore(cr);
  char caption[160];
  std::snprintf(caption, sizeof(caption), "step %lld   t = %.1f s   (%gx speed)", static_cast<long long>(poses.step),
                static_cast<double>(poses.step) * kStepS, options_.speed);
  painter.Caption(0, run_label_ + caption);
  if (overlays_.violations.total() > 0) painter.Caption(1, ViolationsSoFar(poses.step));
  cairo_surface_flush(surfaces_->frame.get());
}

std::string RunAnimation::ViolationsSoFar(int64_t step) const {
  const world::LocatedViolations& violations = overlays_.violations;
  int64_t begun = 0;
  for (const world::LocatedViolation& v : violations.listed) begun += v.first_step <= step ? 1 : 0;
  std::string text = "violations so far: " + std::to_string(begun) + " of " + std::to_string(violations.listed.size());
  if (violations.unlisted > 0) text += " marked (" + std::to_string(violations.unlisted) + " more not marked)";
  return text + " (summary.json violations_located)";
}

const unsigned char* RunAnimation::pixels() const { return cairo_image_surface_get_data(surfaces_->frame.get()); }

int RunAnimation::stride_bytes() const { return cairo_image_surface_get_stride(surfaces_->frame.get()); }

void RunAnimation::WriteFramePng(int frame, const std::string& png_path) {
  DrawFrame(frame);
  PictureSurface picture(RenderFormat::kPng, layout_.width_px(), layout_.height_px());
  cairo_set_source_surface(picture.cr(), surfaces_->frame.get(), 0, 0);
  cairo_paint(picture.cr());
  picture.Commit(png_path);
}

bool RunAnimation::Write(const std::string& path, RenderFormat format, const std::function<bool()>& cancelled,
                         const Progress& progress) {
  if (IsPictureFormat(format)) throw std::invalid_argument("a video is .mp4 or .gif: " + path);
  return Encode(path, format, cancelled, progress);
}

int RunAnimation::FramesToDraw(RenderFormat format) const {
  if (format != RenderFormat::kGif) return frame_count_;
  const int every = std::max(1, frame_count_ / kPaletteSampleFrames);
  return frame_count_ + (frame_count_ + every - 1) / every;
}

bool RunAnimation::Encode(const std::string& path, RenderFormat format, const std::function<bool()>& cancelled,
                          const Progress& progress) {
  // Created here, exclusively under unguessable names (files::TemporaryFile),
  // before ffmpeg opens them by name: nothing planted in the folder is
  // written through; the video is renamed over `path` once whole.
  files::TemporaryFile video(path);
  files::TemporaryFile palette(path + ".palette", ".png");
  const FfmpegEncoder::Input input{layout_.width_px(), layout_.height_px(), options_.fps};
  const int total = FramesToDraw(format);
  int drawn = 0;
  auto feed = [&](FfmpegEncoder& encoder, int every) {
    for (int frame = 0; frame < frame_count_; frame += every) {
      if (cancelled && cancelled()) return false;
      DrawFrame(frame);
      encoder.WriteFrame(pixels(), stride_bytes());
      if (progress) progress(++drawn, total);
    }
    encoder.Finish();
    return true;
  };
  if (format == RenderFormat::kMp4) {
    FfmpegEncoder encoder(input, {"-c:v", "libx264", "-preset", "veryfast", "-crf", "23", "-pix_fmt", "yuv420p",
                                  "-movflags", "+faststart", "-f", "mp4", video.path()});
    if (!feed(encoder, 1)) return false;
  } else {
    // A GIF has 256 colours: one palette for the whole video (so unchanged
    // pixels stay unchanged and compress), computed from a sample of frames.
    {
      FfmpegEncoder encoder(input, {"-vf", "palettegen=stats_mode=full", "-f", "image2", palette.path()});
      if (!feed(encoder, std::max(1, frame_count_ / kPaletteSampleFrames))) return false;
    }
    FfmpegEncoder encoder(
        input, {"-i", palette.path(), "-lavfi", "[0:v][1:v]paletteuse=dither=bayer:bayer_scale=4:diff_mode=rectangle",
                "-loop", "0", "-f", "gif", video.path()});
    if (!feed(encoder, 1)) return false;
  }
  video.Commit();
  return true;
}

}  // namespace dream::render
