#include "dream/view/video_export_request.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace dream::view {
namespace {

VideoExportRequest Parse(const std::string& query) { return VideoExportRequest::Parse(query, {}, 0, 300); }

std::string RefusalOf(const std::string& query) {
  try {
    Parse(query);
  } catch (const VideoExportRequest::Invalid& e) {
    return e.what();
  }
  return "accepted";
}

TEST(VideoExportRequestTest, NothingAskedIsDreamRendersDefaultVideo) {
  const VideoExportRequest mp4 = Parse("");
  EXPECT_FALSE(mp4.gif);
  EXPECT_EQ(mp4.width_px, 720);
  EXPECT_EQ(mp4.fps, 30);
  EXPECT_EQ(mp4.speed, 4);
  EXPECT_EQ(mp4.trail_s, 10);
  EXPECT_FALSE(mp4.viewport);
  EXPECT_EQ(mp4.first_step, -1);
  EXPECT_EQ(mp4.RenderArguments(),
            (std::vector<std::string>{"--width", "720", "--fps", "30", "--speed", "4", "--trail", "10"}));
  const VideoExportRequest gif = Parse("format=gif");
  EXPECT_TRUE(gif.gif);
  EXPECT_EQ(gif.width_px, 480);
  EXPECT_EQ(gif.fps, 15);
  EXPECT_EQ(gif.Extension(), "gif");
}

TEST(VideoExportRequestTest, WhatThePageShowsBecomesDreamRendersOptions) {
  const VideoExportRequest request = Parse(
      "format=mp4&width=1280&fps=24&speed=2&trail=0&x0=-1.2&y0=-0.8&x1=0.3&y1=0.4&from=30&to=150&goals=0&"
      "violations=0&ids=0&drawings=0&radio=1&sensors=1");
  ASSERT_TRUE(request.viewport);
  EXPECT_DOUBLE_EQ(request.viewport->x_min_m, -1.2);
  EXPECT_DOUBLE_EQ(request.viewport->y_max_m, 0.4);
  EXPECT_EQ(request.first_step, 30);
  EXPECT_EQ(request.last_step, 150);
  EXPECT_EQ(
      request.RenderArguments(),
      (std::vector<std::string>{"--width", "1280", "--fps", "24", "--speed", "2", "--trail", "0",
                                "--viewport=-1.2,-0.8,0.3,0.4", "--steps", "30-150", "--no-goals", "--no-violations",
                                "--no-ids", "--no-drawings", "--radio-links", "--sensor-ranges"}));
}

TEST(VideoExportRequestTest, ValuesAreKeptAsThePrintedCommandGivesThem) {
  // The command says --speed 0.333333 and --viewport to the millimetre: the export draws exactly that.
  const VideoExportRequest request = Parse("speed=0.33333333333&x0=-1.23456&y0=-0.5&x1=0.5&y1=0.5");
  EXPECT_EQ(request.speed, 0.333333);
  EXPECT_EQ(request.viewport->x_min_m, -1.235);
  EXPECT_EQ(request.RenderArguments()[5], "0.333333");
}

TEST(VideoExportRequestTest, FramesAreCountedAsTheAnimationCountsThem) {
  // 300 steps = 9.9 s at 4x = 2.475 s at 30 fps: 75 frames, then the end held 30 frames.
  EXPECT_EQ(Parse("").FrameCount(0, 300), 75 + 1 + 30);
  EXPECT_EQ(Parse("from=100&to=160&speed=2&fps=10").FrameCount(0, 300), 10 + 1 + 10);
}

TEST(VideoExportRequestTest, HostileQueriesAreRefusedNamingTheParameterAndValue) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"bogus=1", "bogus: not a parameter"},
      {"fps=10&fps=20", "fps: given twice"},
      {"fps", "fps: no value"},
      {"format=avi", "format=avi: expected mp4 or gif"},
      {"width=100000", "width=100000: out of bounds 160..1920"},
      {"width=720.5", "width=720.5: not a whole number"},
      {"width=", "width=: not a number"},
      {"fps=0", "fps=0: out of bounds"},
      {"fps=1e999", "fps=1e999: not a number"},
      {"speed=-4", "speed=-4: out of bounds"},
      {"speed=nan", "speed=nan: not a number"},
      {"speed=0x10", "speed=0x10"},
      {"trail=601", "trail=601: out of bounds"},
      {"x0=0&y0=0", "x0, y0, x1, y1: give all four"},
      {"x0=-50&y0=-1&x1=1&y1=1", "past the arena"},
      {"x0=0&y0=0&x1=0.01&y1=1", "at least 0.1 m"},
      {"x0=1&y0=0&x1=0&y1=1", "at least 0.1 m"},
      {"from=10", "from, to: give both"},
      {"from=0&to=301", "from=0&to=301: not in the run (steps 0-300)"},
      {"from=100&to=5", "from=100&to=5: from is after to"},
      {"from=-3&to=5", "from=-3: not a step"},
      {"from=1234567890123&to=5", "not a step"},
      {"speed=0.01&fps=60", "frames, over 36000"},
      {"goals=yes", "goals=yes: expected 0 or 1"},
      {"drawings=2", "drawings=2: expected 0 or 1"},
      {"speed=" + std::string(40, '1'), "speed: value over 24 chars"},
  };
  for (const auto& [query, reason] : cases) {
    const std::string refusal = RefusalOf(query);
    EXPECT_NE(refusal.find(reason), std::string::npos) << query << ": " << refusal;
  }
  std::string many;
  for (int i = 0; i < 30; ++i) many += "goals=1&";
  EXPECT_NE(RefusalOf(many).find("goals: given twice"), std::string::npos);
  std::string too_many;
  for (int i = 0; i < 30; ++i) too_many += "&&";
  EXPECT_EQ(RefusalOf(too_many), "accepted");  // empty pairs are nothing
}

}  // namespace
}  // namespace dream::view
