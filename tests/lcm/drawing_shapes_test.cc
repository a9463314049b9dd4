// lcm::DrawingShapes: a drawing_t checked against its type's rules and read as shapes.
#include "dream/lcm/drawing_shapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/sample_lcm_messages.h"
#include "dream/drawing_t.hpp"
#include "dream/lcm/lcm_typed.h"

namespace dream::lcm {
namespace {

// A line from (0, 0) to (1, 0.5), then "hi" at (-0.5, 0.5).
using dream::testing::SampleDrawing;

TEST(DrawingShapesTest, ReadsEachShapesPointsAndTextInOrder) {
  const drawing_t drawing = SampleDrawing();
  EXPECT_EQ(DrawingShapes::Problem(drawing), "");
  const std::vector<DrawnShape> shapes = DrawingShapes::Of(drawing);
  ASSERT_EQ(shapes.size(), 2u);
  EXPECT_EQ(shapes[0].kind, drawing_t::LINE);
  EXPECT_EQ(shapes[0].rgba, 0xff0000ffu);
  EXPECT_EQ(shapes[0].x_m, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(shapes[0].y_m, (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(shapes[0].text, "");
  EXPECT_EQ(shapes[1].x_m, (std::vector<double>{-0.5}));
  EXPECT_EQ(shapes[1].text, "hi");
  EXPECT_DOUBLE_EQ(shapes[1].size_m, 0.05);
}

TEST(DrawingShapesTest, SurvivesTheWire) {
  const drawing_t sent = SampleDrawing();
  std::vector<uint8_t> bytes(static_cast<size_t>(sent.getEncodedSize()));
  sent.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  drawing_t heard;
  ASSERT_TRUE(Decode(bytes.data(), static_cast<int>(bytes.size()), &heard));
  EXPECT_EQ(DrawingShapes::Of(heard).size(), 2u);
}

TEST(DrawingShapesTest, NamesWhatMakesAMessageNoDrawing) {
  const std::vector<std::pair<std::string, void (*)(drawing_t*)>> cases = {
      {"shape 0: kind 0 is none of LINE..TEXT (1..5)", [](drawing_t* d) { d->kind[0] = 0; }},
      {"shape 0: a line has 2 point(s), got 3",
       [](drawing_t* d) {
         d->point_count = {3, 0};
       }},
      {"shape 1: a text has 1 point(s), got 0",
       [](drawing_t* d) {
         d->point_count = {3, 0};
         d->kind[0] = 3;
       }},
      {"the shapes have 4 points and 0 text bytes, the message 3 and 2",
       [](drawing_t* d) {
         d->point_count = {2, 2};
         d->kind[1] = drawing_t::ARROW;
         d->text_length = {0, 0};
       }},
      {"point 1 is not finite or past 100 m", [](drawing_t* d) { d->x[1] = std::nan(""); }},
      {"point 2 is not finite or past 100 m", [](drawing_t* d) { d->y[2] = 1e9; }},
      {"shape 0: width and size must be 0 to 10 m", [](drawing_t* d) { d->width[0] = -1; }},
      {"shape 0: fill must be 0 or 1", [](drawing_t* d) { d->fill[0] = 2; }},
      {"shape 0: text_length 2 (a text has 0 to 96 bytes, another shape none)",
       [](drawing_t* d) {
         d->text_length = {2, 0};
       }},
      {"text byte 0 is not UTF-8", [](drawing_t* d) { d->text[0] = static_cast<uint8_t>(0xff); }},
      {"text holds a control character (10)", [](drawing_t* d) { d->text[1] = '\n'; }},
      {"array sizes do not match their counts", [](drawing_t* d) { d->num_shapes = 3; }},
      {"clipped is negative (-1)", [](drawing_t* d) { d->clipped = -1; }},
  };
  for (const auto& [expected, spoil] : cases) {
    drawing_t drawing = SampleDrawing();
    spoil(&drawing);
    EXPECT_EQ(DrawingShapes::Problem(drawing), expected);
    EXPECT_TRUE(DrawingShapes::Of(drawing).empty()) << expected;
  }
}

}  // namespace
}  // namespace dream::lcm
