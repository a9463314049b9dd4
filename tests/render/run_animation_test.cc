#include "dream/render/run_animation.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "picture_pixels.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"
#include "video_probe.h"

namespace dream::render {
namespace {

using dream::testing::Box;
using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;
using testing::kObstacleGrey;
using testing::kRobot0Blue;
using testing::kWhite;
using testing::PicturePixels;

// Inside a robot's disc (radius 0.055 m), clear of its id label, its heading
// tick (+x here) and the grid lines through its centre.
constexpr double kOffsetM = 0.03;

class RunAnimationTest : public ::testing::Test {
 protected:
  RunAnimationTest() : run_(run_log::RunLog::Read(SyntheticRunLog::TwoRobots(dir_ / "run.lcmlog", 300).Write())) {}

  AnimationOptions Options() const {
    AnimationOptions options;
    options.width_px = 640;
    options.fps = 10;
    options.speed = 2;
    options.hold_end_s = 0.5;
    return options;
  }

  TempFolder dir_;
  run_log::RunLog run_;
  ArenaOverlays no_overlays_;
};

TEST_F(RunAnimationTest, FramesFollowDurationFpsAndSpeed) {
  const RunAnimation animation(run_, no_overlays_, Options());
  // 300 steps = 9.9 s at 2x = 4.95 s of video at 10 fps: frames 0..50 (the
  // last clamped to the final step), then 0.5 s = 5 frames holding it.
  EXPECT_EQ(animation.frame_count(), 56);
  EXPECT_DOUBLE_EQ(animation.duration_s(), 5.6);
  EXPECT_EQ(animation.StepOfFrame(0), 0);
  EXPECT_EQ(animation.StepOfFrame(10), 61);  // 2 s simulated / 0.033 s
  EXPECT_EQ(animation.StepOfFrame(50), 300);
  EXPECT_EQ(animation.StepOfFrame(55), 300);
  EXPECT_EQ(animation.layout().width_px(), 640);
  EXPECT_EQ(animation.layout().height_px() % 2, 0);
}

TEST_F(RunAnimationTest, FramesHaveTickLabelsALegendAndTheRunsName) {
  ArenaOverlays overlays;
  overlays.run_name = "demo";
  overlays.verdict = "clean";
  RunAnimation named(run_, overlays, Options());
  RunAnimation plain(run_, no_overlays_, Options());
  named.WriteFramePng(0, dir_ / "named.png");
  plain.WriteFramePng(0, dir_ / "plain.png");
  const PicturePixels with(dir_ / "named.png");
  const PicturePixels without(dir_ / "plain.png");
  const ArenaLayout& layout = named.layout();
  // A y tick label left of the frame at y = 0, an x one under it at x = 0.
  EXPECT_GT(with.CountInk(0, layout.py(0.0) - 5, layout.px(-1.6) - 2, layout.py(0.0) + 5), 5);
  EXPECT_GT(with.CountInk(layout.px(0) - 8, layout.py(-1.0) + 3, layout.px(0) + 8, layout.py(-1.0) + 14), 3);
  // The legend's robot disc, in robot 0's colour.
  const double top = layout.legend_center_px() - layout.legend_row_px() / 2;
  EXPECT_GT(with.CountNear(0, top, layout.width_px(), top + layout.legend_row_px(), kRobot0Blue, 20), 20);
  // The caption starts with the run's name and verdict: more ink on that line.
  const double baseline = layout.caption_baseline_px(0);
  EXPECT_GT(with.CountInk(0, baseline - 12, layout.width_px(), baseline + 3),
            without.CountInk(0, baseline - 12, layout.width_px(), baseline + 3) + 50);
}

TEST_F(RunAnimationTest, EachFrameShowsTheRobotsWhereTheyAreThen) {
  RunAnimation animation(run_, no_overlays_, Options());
  const ArenaLayout& layout = animation.layout();
  animation.WriteFramePng(0, dir_ / "first.png");
  animation.WriteFramePng(animation.frame_count() - 1, dir_ / "last.png");
  const PicturePixels first(dir_ / "first.png");
  const PicturePixels last(dir_ / "last.png");
  EXPECT_EQ(first.width(), layout.width_px());
  auto start = [&](const PicturePixels& p, const auto& rgb, int tolerance) {
    return p.Near(layout.px(-1.0 + kOffsetM), layout.py(-kOffsetM), rgb, tolerance);
  };
  auto end = [&](const PicturePixels& p, const auto& rgb, int tolerance) {
    return p.Near(layout.px(1.0 + kOffsetM), layout.py(0.5 - kOffsetM), rgb, tolerance);
  };
  EXPECT_TRUE(start(first, kRobot0Blue, 20));
  EXPECT_TRUE(end(first, kWhite, 0));
  EXPECT_TRUE(end(last, kRobot0Blue, 20));
  EXPECT_TRUE(start(last, kWhite, 0));
}

TEST_F(RunAnimationTest, TrailsCoverTheLastSecondsOnly) {
  AnimationOptions options = Options();
  options.trail_s = 3.0;
  RunAnimation with_trail(run_, no_overlays_, options);
  options.trail_s = 0.0;
  RunAnimation without_trail(run_, no_overlays_, options);
  const int last = with_trail.frame_count() - 1;
  with_trail.WriteFramePng(last, dir_ / "trail.png");
  without_trail.WriteFramePng(last, dir_ / "none.png");
  const PicturePixels trail(dir_ / "trail.png");
  const PicturePixels none(dir_ / "none.png");
  const ArenaLayout& layout = with_trail.layout();
  // Robot 0 drives x = -1 + 2u, y = 0.5u over 9.9 s: 1.5 s before the end it
  // was at u = 0.85 (inside the trail), 6 s before at u = 0.39 (outside).
  auto at = [&](double u) { return std::array<double, 2>{layout.px(-1 + 2 * u), layout.py(0.5 * u)}; };
  EXPECT_FALSE(trail.Near(at(0.85)[0], at(0.85)[1], kWhite, 30));
  EXPECT_TRUE(none.Near(at(0.85)[0], at(0.85)[1], kWhite, 0));
  EXPECT_TRUE(trail.Near(at(0.39)[0], at(0.39)[1], kWhite, 0));
}

TEST_F(RunAnimationTest, MovingObstaclesAreWhereTheyAreAtEachFrame) {
  SyntheticRunLog log(dir_ / "moving.lcmlog");
  for (int step = 0; step <= 100; ++step) {
    log.Poses(step, {{0, 0, 0}}).Obstacles(step, {Box(0, -1.0 + 0.02 * step, 0.6, 0.2, 0.2)});
  }
  const run_log::RunLog run = run_log::RunLog::Read(log.Write());
  RunAnimation animation(run, no_overlays_, Options());
  animation.WriteFramePng(0, dir_ / "first.png");
  animation.WriteFramePng(animation.frame_count() - 1, dir_ / "last.png");
  const PicturePixels first(dir_ / "first.png");
  const PicturePixels last(dir_ / "last.png");
  const ArenaLayout& layout = animation.layout();
  EXPECT_TRUE(first.Near(layout.px(-1.0), layout.py(0.65), kObstacleGrey));
  EXPECT_TRUE(last.Near(layout.px(1.0), layout.py(0.65), kObstacleGrey));
  EXPECT_FALSE(last.Near(layout.px(-1.0), layout.py(0.65), kObstacleGrey, 60));
}

TEST_F(RunAnimationTest, OptionsOutOfRangeAreRefusedNamingThem) {
  auto refused = [&](AnimationOptions options, const std::string& option) {
    try {
      RunAnimation animation(run_, no_overlays_, options);
      ADD_FAILURE() << option << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
  };
  AnimationOptions options = Options();
  options.fps = 0;
  refused(options, "--fps");
  options = Options();
  options.speed = -1;
  refused(options, "--speed");
  options = Options();
  options.trail_s = -2;
  refused(options, "--trail");
  options = Options();
  options.width_px = 20;
  refused(options, "--width");
}

TEST_F(RunAnimationTest, AStepRangeShowsThoseStepsOnly) {
  AnimationOptions options = Options();
  options.first_step = 100;
  options.last_step = 160;
  options.hold_end_s = 0;
  const RunAnimation animation(run_, no_overlays_, options);
  // 60 steps = 1.98 s at 2x = 0.99 s of video at 10 fps: frames 0..10.
  EXPECT_EQ(animation.frame_count(), 11);
  EXPECT_EQ(animation.StepOfFrame(0), 100);
  EXPECT_EQ(animation.StepOfFrame(5), 130);
  EXPECT_EQ(animation.StepOfFrame(10), 160);
  auto refused = [&](int64_t first, int64_t last, const std::string& reason) {
    AnimationOptions bad = Options();
    bad.first_step = first;
    bad.last_step = last;
    try {
      RunAnimation refused_animation(run_, no_overlays_, bad);
      ADD_FAILURE() << first << "-" << last << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
  };
  refused(160, 100, "the first step 160 is after the last 100");
  refused(0, 301, "the last step 301 is not in the run (steps 0-300)");
}

TEST_F(RunAnimationTest, AViewportZoomsOnItsPartOfTheWorldAndClipsTheRest) {
  AnimationOptions options = Options();
  // Robot 0 starts at (-1, 0): a viewport round it, a quarter of the arena wide.
  options.viewport = Viewport{-1.4, -0.25, -0.6, 0.25};
  RunAnimation zoomed(run_, no_overlays_, options);
  const ArenaLayout& layout = zoomed.layout();
  EXPECT_DOUBLE_EQ(layout.scale(), 4 * layout.frame_scale());
  zoomed.WriteFramePng(0, dir_ / "zoomed.png");
  const PicturePixels picture(dir_ / "zoomed.png");
  EXPECT_EQ(picture.width(), 640);
  // Its disc, four times as wide, where it is in the world.
  EXPECT_TRUE(picture.Near(layout.px(-1.0 + kOffsetM), layout.py(-kOffsetM), kRobot0Blue, 20));
  EXPECT_GT(picture.CountNear(0, 0, picture.width(), picture.height(), kRobot0Blue, 20),
            10 * 3.14 * 0.05 * 0.05 * layout.frame_scale() * layout.frame_scale());
  EXPECT_NEAR(layout.px(-1.0), (layout.frame_left_px() + layout.frame_right_px()) / 2, 1e-9);
  // Robot 1 (at (1, 0)) is outside the viewport: nothing of it in the margins either.
  EXPECT_EQ(picture.CountNear(0, 0, picture.width(), layout.frame_bottom_px(), testing::kRobot1Orange, 20), 0);
  // The margin right of the frame stays white (the arena's grid and walls clipped).
  EXPECT_EQ(picture.CountInk(layout.frame_right_px() + 3, layout.frame_top_px() + 3, picture.width(),
                             layout.frame_bottom_px() - 3),
            0);
}

TEST_F(RunAnimationTest, ProgressCountsEveryFrameDrawn) {
  if (!testing::OnPath("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  RunAnimation animation(run_, no_overlays_, Options());
  for (const RenderFormat format : {RenderFormat::kMp4, RenderFormat::kGif}) {
    int last_drawn = 0;
    int calls = 0;
    const int total = animation.FramesToDraw(format);
    ASSERT_TRUE(animation.Write(dir_ / (format == RenderFormat::kGif ? "run.gif" : "run.mp4"), format, {},
                                [&](int drawn, int of) {
                                  EXPECT_EQ(drawn, last_drawn + 1);
                                  EXPECT_EQ(of, total);
                                  last_drawn = drawn;
                                  ++calls;
                                }));
    EXPECT_EQ(last_drawn, total);
    EXPECT_EQ(calls, total);
  }
  EXPECT_EQ(animation.FramesToDraw(RenderFormat::kMp4), animation.frame_count());
  EXPECT_GT(animation.FramesToDraw(RenderFormat::kGif), animation.frame_count());
}

TEST_F(RunAnimationTest, Mp4AndGifHoldEveryFrame) {
  if (!testing::OnPath("ffmpeg") || !testing::OnPath("ffprobe")) GTEST_SKIP() << "ffmpeg is not installed";
  AnimationOptions options = Options();
  options.speed = 5;  // 21 frames of the run and 5 held
  RunAnimation animation(run_, no_overlays_, options);
  ASSERT_TRUE(animation.Write(dir_ / "run.mp4", RenderFormat::kMp4));
  ASSERT_TRUE(animation.Write(dir_ / "run.gif", RenderFormat::kGif));
  EXPECT_EQ(testing::CountVideoFrames(dir_ / "run.mp4"), animation.frame_count());
  EXPECT_EQ(testing::CountVideoFrames(dir_ / "run.gif"), animation.frame_count());
  auto files = dir_.Files();
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"run.gif", "run.lcmlog", "run.mp4"}));  // no temporary files
}

TEST_F(RunAnimationTest, ACancelledVideoLeavesNothingBehind) {
  if (!testing::OnPath("ffmpeg")) GTEST_SKIP() << "ffmpeg is not installed";
  RunAnimation animation(run_, no_overlays_, Options());
  int frames_drawn = 0;
  EXPECT_FALSE(animation.Write(dir_ / "run.mp4", RenderFormat::kMp4, [&] { return ++frames_drawn > 5; }));
  EXPECT_FALSE(animation.Write(dir_ / "run.gif", RenderFormat::kGif, [&] { return true; }));
  EXPECT_EQ(dir_.Files(), std::vector<std::string>{"run.lcmlog"});
}

}  // namespace
}  // namespace dream::render
