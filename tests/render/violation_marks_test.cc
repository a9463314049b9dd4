// Violations located on a run's log (LocateViolations) and marked where they
// happened in pictures and video frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "dream/files/stop_token.h"
#include "dream/files/stopped.h"
#include "dream/render/arena_layout.h"
#include "dream/render/run_animation.h"
#include "dream/render/run_geometry.h"
#include "dream/render/trajectory_picture.h"
#include "picture_pixels.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::render {
namespace {

using dream::testing::Box;
using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;
using testing::PicturePixels;
using Kind = world::LocatedViolation::Kind;

constexpr std::array<double, 3> kRed = {0.84, 0.08, 0.08};
constexpr double kRingRadiusM = 0.13;

/// 100 steps: robot 1 touches robot 0 (steps 40..60, at (-0.45, 0.3)),
/// leaves the arena (80..84, at x 1.62) and stands on obstacle 7 (90..92);
/// robot 0 ends outside the arena, at the final poses the world never checks.
std::string ViolatingRun(const TempFolder& dir) {
  SyntheticRunLog log(dir / "run.lcmlog");
  log.Obstacles(0, {Box(7, 0.5, -0.5, 0.2, 0.2)});
  for (int step = 0; step <= 100; ++step) {
    std::array<double, 3> one = {0.0, 0.3, 0.0};
    if (step >= 40 && step <= 60) one = {-0.4, 0.3, 0.0};
    if (step >= 80 && step <= 84) one = {1.62, 0.3, 0.0};
    if (step >= 90 && step <= 92) one = {0.5, -0.5, 0.0};
    log.Poses(step, {{step == 100 ? 1.8 : -0.5, 0.3, 0.0}, one});
  }
  return log.Write();
}

// dream render polls its stop token (Ctrl-C, SIGTERM) while locating a long
// run's violations, every 1000 steps (issue 34): a 2,500-step run is asked 3
// times, and a stop asked at the second poll ends it there.
TEST(LocateViolationsTest, AStopAskedForWhileLocatingEndsItAtTheNextPoll) {
  const TempFolder dir;
  SyntheticRunLog log(dir / "run.lcmlog");
  for (int step = 0; step < 2500; ++step) log.Poses(step, {{-0.5, 0.3, 0.0}, {0.5, 0.3, 0.0}});
  const run_log::RunLog run = run_log::RunLog::Read(log.Write());
  int polls = 0;
  LocateViolations(run, {}, world::ViolationTracker::kDefaultMaxListed, files::StopToken([&polls] {
                     ++polls;
                     return false;
                   }));
  EXPECT_EQ(polls, 3);
  polls = 0;
  EXPECT_THROW(LocateViolations(run, {}, world::ViolationTracker::kDefaultMaxListed,
                                files::StopToken([&polls] { return ++polls == 2; })),
               files::Stopped);
  EXPECT_EQ(polls, 2);
}

TEST(LocateViolationsTest, EachViolationOfTheLogAtItsPlaceFirstAndLastStepByTheWorldsRules) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(ViolatingRun(dir));
  const world::LocatedViolations located = LocateViolations(run);
  ASSERT_EQ(located.listed.size(), 3u);
  EXPECT_EQ(located.unlisted, 0);
  const world::LocatedViolation& collision = located.listed[0];
  EXPECT_EQ(collision.kind, Kind::kCollision);
  EXPECT_EQ(collision.robot, 0);
  EXPECT_EQ(collision.other, 1);
  EXPECT_EQ(collision.first_step, 40);
  EXPECT_EQ(collision.last_step, 60);
  EXPECT_DOUBLE_EQ(collision.x_m, -0.45);
  EXPECT_DOUBLE_EQ(collision.y_m, 0.3);
  const world::LocatedViolation& boundary = located.listed[1];
  EXPECT_EQ(boundary.kind, Kind::kBoundary);
  EXPECT_EQ(boundary.robot, 1);
  EXPECT_EQ(boundary.first_step, 80);
  EXPECT_EQ(boundary.last_step, 84);
  EXPECT_DOUBLE_EQ(boundary.x_m, 1.62);
  const world::LocatedViolation& obstacle = located.listed[2];
  EXPECT_EQ(obstacle.kind, Kind::kObstacle);
  EXPECT_EQ(obstacle.other, 7);
  EXPECT_EQ(obstacle.first_step, 90);
  EXPECT_EQ(obstacle.last_step, 92);
}

TEST(LocateViolationsTest, TheListIsBoundedAndTheRestCounted) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(ViolatingRun(dir));
  const world::LocatedViolations located = LocateViolations(run, world::WorldParams{}, 1);
  ASSERT_EQ(located.listed.size(), 1u);
  EXPECT_EQ(located.listed[0].first_step, 40);
  EXPECT_EQ(located.unlisted, 2);
}

TEST(LocateViolationsTest, ACleanRunHasNone) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(SyntheticRunLog::TwoRobots(dir / "run.lcmlog", 50).Write());
  EXPECT_EQ(LocateViolations(run).total(), 0);
}

/// Red pixels in a square of `half_px` round pixel (x, y).
int RedNear(const PicturePixels& picture, double x, double y, double half_px) {
  return picture.CountNear(x - half_px, y - half_px, x + half_px, y + half_px, kRed, 40);
}

TEST(ViolationMarksTest, ThePictureMarksEachViolationAtItsPlaceWithItsFirstStepAndNothingElseRed) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(ViolatingRun(dir));
  ArenaOverlays overlays;
  overlays.violations = LocateViolations(run);
  const std::string marked = dir / "marked.png";
  const std::string plain = dir / "plain.png";
  TrajectoryPicture::Render(run, overlays, marked, RenderFormat::kPng, 1280);
  TrajectoryPicture::Render(run, ArenaOverlays{}, plain, RenderFormat::kPng, 1280);
  const ArenaLayout layout(1280, 2);  // a second caption line counts the violations
  const PicturePixels picture(marked);
  ASSERT_EQ(picture.height(), layout.height_px());
  const double ring_px = kRingRadiusM * layout.scale();
  for (const world::LocatedViolation& v : overlays.violations.listed) {
    const double x = layout.px(v.x_m);
    const double y = layout.py(v.y_m);
    // The ring's left and bottom edges, and its label "k=<first step>" at
    // one of its corners (to the right above unless off the picture).
    EXPECT_GT(RedNear(picture, x - ring_px, y, 3), 0) << "ring left of k=" << v.first_step;
    EXPECT_GT(RedNear(picture, x, y + ring_px, 3), 0) << "ring below k=" << v.first_step;
    int label = 0;
    for (const double left : {x + 0.8 * ring_px, x - 0.8 * ring_px - 40}) {
      for (const double top : {y - 0.8 * ring_px - 16, y + 0.8 * ring_px}) {
        label +=
            picture.CountNear(std::max(left, 0.0), top, std::min(left + 40, picture.width() - 1.0), top + 16, kRed, 40);
      }
    }
    EXPECT_GT(label, 5) << "label of k=" << v.first_step;
  }
  // Where robot 0 ended outside the arena (the final poses, never checked): no mark.
  EXPECT_EQ(RedNear(picture, layout.px(1.8) - ring_px, layout.py(0.3), 3), 0);
  const ArenaLayout plain_layout(1280, 1);
  const PicturePixels without(plain);
  EXPECT_EQ(without.height(), plain_layout.height_px());
  EXPECT_EQ(without.CountNear(0, 0, without.width(), without.height(), kRed, 40), 0);
}

TEST(ViolationMarksTest, MarksAtOnePlaceAreOneRingWithOneLabelCountingTheOthers) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(SyntheticRunLog::TwoRobots(dir / "run.lcmlog", 50).Write());
  ArenaOverlays one;
  one.violations.listed.push_back({Kind::kObstacle, 1, 3, 40, 45, -0.8, -0.6});
  ArenaOverlays three = one;  // two more at (nearly) the same place
  three.violations.listed.push_back({Kind::kObstacle, 1, 4, 50, 50, -0.8, -0.6});
  three.violations.listed.push_back({Kind::kBoundary, 1, -1, 20, 20, -0.79, -0.6});
  TrajectoryPicture::Render(run, one, dir / "one.png", RenderFormat::kPng, 1280);
  TrajectoryPicture::Render(run, three, dir / "three.png", RenderFormat::kPng, 1280);
  const PicturePixels single(dir / "one.png");
  const PicturePixels merged(dir / "three.png");
  const ArenaLayout layout(1280, 2);
  const double ring_px = kRingRadiusM * layout.scale();
  const double x = layout.px(-0.8);
  const double y = layout.py(-0.6);
  // One label, at the upper right: "k=40" alone, "k=20 +2" (wider) merged.
  auto upper_right = [&](const PicturePixels& p) {
    return p.CountNear(x + 0.8 * ring_px, y - 0.8 * ring_px - 16, x + 0.8 * ring_px + 90, y - 0.8 * ring_px, kRed, 40);
  };
  auto other_corners = [&](const PicturePixels& p) {
    return p.CountNear(x + 0.8 * ring_px, y + 0.8 * ring_px, x + 0.8 * ring_px + 60, y + 0.8 * ring_px + 16, kRed, 40) +
           p.CountNear(x - 0.8 * ring_px - 60, y - 0.8 * ring_px - 16, x - 0.8 * ring_px, y - 0.8 * ring_px, kRed, 40);
  };
  EXPECT_GT(upper_right(single), 5);
  EXPECT_GT(upper_right(merged), upper_right(single) + 5);
  EXPECT_EQ(other_corners(single), 0);
  EXPECT_EQ(other_corners(merged), 0);  // no second or third label
}

// An episode is labelled with its steps: "k=40-95" is wider than one step's "k=40".
TEST(ViolationMarksTest, AnEpisodesLabelGivesItsFirstAndLastStep) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(SyntheticRunLog::TwoRobots(dir / "run.lcmlog", 100).Write());
  ArenaOverlays step;
  step.violations.listed.push_back({Kind::kObstacle, 1, 3, 40, 40, -0.8, -0.6});
  ArenaOverlays episode;
  episode.violations.listed.push_back({Kind::kObstacle, 1, 3, 40, 95, -0.8, -0.6});
  TrajectoryPicture::Render(run, step, dir / "step.png", RenderFormat::kPng, 1280);
  TrajectoryPicture::Render(run, episode, dir / "episode.png", RenderFormat::kPng, 1280);
  const ArenaLayout layout(1280, 2);
  const double ring_px = kRingRadiusM * layout.scale();
  const double x = layout.px(-0.8);
  const double y = layout.py(-0.6);
  auto label = [&](const PicturePixels& p) {
    return p.CountNear(x + 0.8 * ring_px, y - 0.8 * ring_px - 16, x + 0.8 * ring_px + 120, y - 0.8 * ring_px, kRed, 40);
  };
  const PicturePixels one_step(dir / "step.png");
  const PicturePixels many(dir / "episode.png");
  EXPECT_GT(label(one_step), 5);
  EXPECT_GT(label(many), label(one_step) + 5);
}

TEST(ViolationMarksTest, TheCaptionCountsThemAndSaysWhatIsNotMarked) {
  world::LocatedViolations violations;
  violations.listed.push_back({Kind::kCollision, 0, 1, 40, 60, 0.0, 0.0});
  violations.listed.push_back({Kind::kBoundary, 1, -1, 12, 12, 0.0, 0.0});
  EXPECT_EQ(TrajectoryPicture::ViolationCaption(violations),
            "2 violations, the first at k=12 (summary.json violations_located)");
  violations.unlisted = 5;
  EXPECT_EQ(TrajectoryPicture::ViolationCaption(violations),
            "7 violations, the first at k=12; 2 marked, 5 more not (summary.json violations_located)");
}

TEST(ViolationMarksTest, AVideoMarksAViolationFromItsFirstStepOn) {
  const TempFolder dir;
  const run_log::RunLog run = run_log::RunLog::Read(ViolatingRun(dir));
  ArenaOverlays overlays;
  overlays.violations = LocateViolations(run);
  AnimationOptions options;
  options.width_px = 640;
  options.fps = 30;
  options.speed = 1;  // a frame a step
  RunAnimation animation(run, overlays, options);
  const ArenaLayout& layout = animation.layout();
  const double ring_px = kRingRadiusM * layout.scale();
  const world::LocatedViolation& collision = overlays.violations.listed[0];
  auto frame_at = [&](int64_t step) {
    int frame = 0;
    while (animation.StepOfFrame(frame) < step) ++frame;
    const std::string png = dir / ("frame" + std::to_string(step) + ".png");
    animation.WriteFramePng(frame, png);
    return png;
  };
  const PicturePixels before(frame_at(collision.first_step - 5));
  const PicturePixels during(frame_at(collision.first_step + 1));
  const double x = layout.px(collision.x_m) - ring_px;
  const double y = layout.py(collision.y_m);
  EXPECT_EQ(RedNear(before, x, y, 3), 0);
  EXPECT_GT(RedNear(during, x, y, 3), 0);
}

}  // namespace
}  // namespace dream::render
