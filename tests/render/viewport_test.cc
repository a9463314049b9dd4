#include "dream/render/viewport.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "dream/render/arena_layout.h"

namespace dream::render {
namespace {

std::string RefusalOf(const std::string& text) {
  try {
    Viewport::Parse(text);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ViewportTest, ParsesFourNumbersAndWritesThemBack) {
  const Viewport v = Viewport::Parse("-0.8,-0.5,0.4,0.25");
  EXPECT_DOUBLE_EQ(v.x_min_m, -0.8);
  EXPECT_DOUBLE_EQ(v.y_min_m, -0.5);
  EXPECT_DOUBLE_EQ(v.x_max_m, 0.4);
  EXPECT_DOUBLE_EQ(v.y_max_m, 0.25);
  EXPECT_EQ(v.Text(), "-0.8,-0.5,0.4,0.25");
  EXPECT_EQ(Viewport::Parse(v.Text()).Text(), v.Text());
  EXPECT_EQ((Viewport{0.00001, -1.23456, 1, 2}).Text(), "0,-1.235,1,2");
}

TEST(ViewportTest, RefusesWhatIsNotAViewportNamingTheOptionAndValue) {
  for (const std::string bad :
       {"", "1,2,3", "1,2,3,4,5", "a,b,c,d", "0,0,1,", "0,0,1,1x", ",0,1,1", "nan,0,1,1", "0,0,inf,1"}) {
    const std::string refusal = RefusalOf(bad);
    EXPECT_NE(refusal.find("--viewport"), std::string::npos) << bad << ": " << refusal;
  }
  // Too small, upside down, too far out: the reason and the value.
  EXPECT_NE(RefusalOf("0,0,0.05,1").find("at least 0.1 m"), std::string::npos);
  EXPECT_NE(RefusalOf("1,0,0,1").find("at least 0.1 m"), std::string::npos);
  EXPECT_NE(RefusalOf("-9,-1,0,1").find("past the arena"), std::string::npos);
  EXPECT_NE(RefusalOf("-9,-1,0,1").find("-9,-1,0,1"), std::string::npos);
  EXPECT_NE(RefusalOf("0,0,1,1e300").find("past the arena"), std::string::npos);
}

TEST(ViewportTest, AViewportOfTheArenaIsTheArena) {
  const ArenaLayout plain(1280, 1);
  const ArenaLayout same(1280, 1, false, Viewport{-1.6, -1.0, 1.6, 1.0});
  EXPECT_TRUE(same.zoomed());
  EXPECT_FALSE(plain.zoomed());
  for (const double x : {-1.6, 0.0, 0.7}) EXPECT_NEAR(same.px(x), plain.px(x), 1e-9);
  for (const double y : {-1.0, 0.0, 0.3}) EXPECT_NEAR(same.py(y), plain.py(y), 1e-9);
  EXPECT_EQ(same.height_px(), plain.height_px());
}

TEST(ViewportTest, AViewportIsFittedWholeAndCentredInTheFrame) {
  // Half the arena's width and a quarter of its height: the width decides (zoom 2).
  const ArenaLayout layout(1280, 1, false, Viewport{0.0, 0.0, 1.6, 0.5});
  EXPECT_DOUBLE_EQ(layout.scale(), 2 * layout.frame_scale());
  // Its left and right edges are the frame's; its middle is the frame's middle.
  EXPECT_NEAR(layout.px(0.0), layout.frame_left_px(), 1e-9);
  EXPECT_NEAR(layout.px(1.6), layout.frame_right_px(), 1e-9);
  EXPECT_NEAR(layout.py(0.25), (layout.frame_top_px() + layout.frame_bottom_px()) / 2, 1e-9);
  // The frame shows more in y: 1 m (the arena's 2 m halved) round y = 0.25.
  EXPECT_NEAR(layout.visible().y_min_m, -0.25, 1e-12);
  EXPECT_NEAR(layout.visible().y_max_m, 0.75, 1e-12);
  // The picture's size, the legend and the captions do not move with the zoom.
  const ArenaLayout plain(1280, 1);
  EXPECT_EQ(layout.height_px(), plain.height_px());
  EXPECT_DOUBLE_EQ(layout.caption_baseline_px(0), plain.caption_baseline_px(0));
  EXPECT_DOUBLE_EQ(layout.legend_row_px(), plain.legend_row_px());
}

TEST(ViewportTest, GridLinesGetFinerZoomedIn) {
  EXPECT_DOUBLE_EQ(ArenaLayout(1280, 1).grid_step_m(), 0.5);
  EXPECT_DOUBLE_EQ(ArenaLayout(1280, 1, false, Viewport{0, 0, 1.6, 1.0}).grid_step_m(), 0.2);
  EXPECT_DOUBLE_EQ(ArenaLayout(1280, 1, false, Viewport{0, 0, 0.4, 0.4}).grid_step_m(), 0.1);
  EXPECT_DOUBLE_EQ(ArenaLayout(1280, 1, false, Viewport{0, 0, 0.1, 0.1}).grid_step_m(), 0.05);
}

TEST(ViewportTest, ALayoutRefusesABadViewport) {
  EXPECT_THROW(ArenaLayout(1280, 1, false, Viewport{0, 0, 0, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace dream::render
