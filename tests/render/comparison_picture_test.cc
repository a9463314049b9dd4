#include "dream/render/comparison_picture.h"

#include <gtest/gtest.h>

#include "dream/render/arena_layout.h"
#include "picture_pixels.h"
#include "synthetic_run_log.h"
#include "temp_folder.h"

namespace dream::render {
namespace {

using dream::testing::SyntheticRunLog;
using dream::testing::TempFolder;
using testing::kRobot0Blue;
using testing::kWhite;
using testing::PicturePixels;

constexpr double kRobotRadiusM = 0.055;

// Robot 0 drives from (-1, 0) to (1, 0.5) heading +x; robot 1 stands at (0, -0.5) heading up.
TEST(ComparisonPicture, MarksStartsAndNamesEachRobotAtItsEnd) {
  TempFolder dir;
  const std::string log_path = SyntheticRunLog::TwoRobots(dir / "run.lcmlog", 100).Write();
  const run_log::RunLog log = run_log::RunLog::Read(log_path);
  const std::string png = dir / "comparison.png";
  ComparisonPicture::Render(log, log, png, {"robot 1: 0.00 m RMS"});
  const PicturePixels picture(png);
  const ArenaLayout layout(1280, 1);

  // Robot 0's start marker: a small hollow disc round (-1, 0); its left rim is
  // blue, where no track passes (the track leaves to the right).
  const double rim_m = 0.6 * kRobotRadiusM;
  const double rim_x = layout.px(-1.0 - rim_m);
  const int blue = picture.CountNear(rim_x - 2, layout.py(0.0) - 2, rim_x + 3, layout.py(0.0) + 3, kRobot0Blue, 30);
  EXPECT_GT(blue, 0) << "no start marker at robot 0's start";

  // Robot 1's end holds its id in white: a filled disc without one is its
  // colour and a black heading tick only.
  const double half = 0.3 * 0.8 * kRobotRadiusM;
  EXPECT_GT(
      picture.CountNear(layout.px(-half), layout.py(-0.5 + half), layout.px(half), layout.py(-0.5 - half), kWhite, 60),
      0)
      << "no id drawn on robot 1";
}

}  // namespace
}  // namespace dream::render
