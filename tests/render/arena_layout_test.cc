#include "dream/render/arena_layout.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace dream::render {
namespace {

TEST(ArenaLayoutTest, MapsTheArenaCornersInsideTheMarginsWithYUp) {
  const ArenaLayout layout(1280, 1);
  EXPECT_DOUBLE_EQ(layout.px(-1.6), 36.0);
  EXPECT_DOUBLE_EQ(layout.px(1.6), 1244.0);
  EXPECT_DOUBLE_EQ(layout.py(1.0), 36.0);
  EXPECT_GT(layout.py(-1.0), layout.py(1.0));
  EXPECT_DOUBLE_EQ(layout.scale(), 1208.0 / 3.2);
  EXPECT_DOUBLE_EQ(layout.ui_scale(), 1.0);
  // The caption sits below the arena and inside the picture.
  EXPECT_GT(layout.caption_baseline_px(0), layout.py(-1.0));
  EXPECT_LT(layout.caption_baseline_px(0), layout.height_px());
  // The legend row lies between the arena (and its x tick labels) and the caption,
  // tall enough for a robot marker to scale (0.11 m).
  EXPECT_GT(layout.legend_center_px() - layout.legend_row_px() / 2, layout.py(-1.0) + layout.tick_font_px());
  EXPECT_LT(layout.legend_center_px() + layout.legend_row_px() / 2,
            layout.caption_baseline_px(0) - layout.caption_font_px() * 0.7);
  EXPECT_GE(layout.legend_row_px(), 0.11 * layout.scale());
}

TEST(ArenaLayoutTest, VideoFramesHaveEvenSizes) {
  for (int width : {720, 722, 480, 1000, 640}) {
    const ArenaLayout layout(width, 1, /*even_size=*/true);
    EXPECT_EQ(layout.height_px() % 2, 0) << width;
  }
}

TEST(ArenaLayoutTest, MoreCaptionLinesMakeItTaller) {
  EXPECT_GT(ArenaLayout(1280, 2).height_px(), ArenaLayout(1280, 1).height_px());
  EXPECT_GT(ArenaLayout(1280, 1).height_px(), ArenaLayout(1280, 0).height_px());
}

TEST(ArenaLayoutTest, RefusesAbsurdWidths) {
  EXPECT_THROW(ArenaLayout(10, 1), std::invalid_argument);
  EXPECT_THROW(ArenaLayout(100000, 1), std::invalid_argument);
}

}  // namespace
}  // namespace dream::render
