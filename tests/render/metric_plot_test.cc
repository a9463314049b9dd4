#include "dream/render/metric_plot.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "picture_pixels.h"
#include "temp_folder.h"

namespace dream::render {
namespace {

using dream::testing::TempFolder;
using testing::PicturePixels;

MetricSeries Ramp(const std::string& name, int points) {
  MetricSeries series;
  series.name = name;
  for (int i = 0; i < points; ++i) series.points.push_back({i * 10.0, 1.0 - i / static_cast<double>(points)});
  return series;
}

// Counts pixels in a column that are neither white nor grey (the plotted line's colour).
int ColouredPixelsInColumn(const PicturePixels& picture, int x) {
  int count = 0;
  for (int y = 0; y < picture.height(); ++y) {
    const auto rgb = picture.Rgb(x, y);
    if (std::abs(rgb[0] - rgb[1]) > 40 || std::abs(rgb[1] - rgb[2]) > 40) ++count;
  }
  return count;
}

TEST(MetricPlotTest, OnePanelPerSeriesWithItsLine) {
  TempFolder dir;
  const std::string one = dir / "one.png";
  const std::string two = dir / "two.png";
  MetricSeries closest = Ramp("min_distance_m", 50);
  closest.limit = 0.135;
  closest.limit_label = "collision";
  MetricPlot::Render({Ramp("coverage_cost_m4", 100)}, "run", one, RenderFormat::kPng);
  MetricPlot::Render({Ramp("coverage_cost_m4", 100), closest}, "run", two, RenderFormat::kPng);
  const PicturePixels first(one);
  const PicturePixels second(two);
  EXPECT_EQ(first.width(), 1000);
  EXPECT_GT(second.height(), first.height() * 3 / 2);
  // Half way along the time axis each panel's line crosses the column once.
  EXPECT_GE(ColouredPixelsInColumn(first, first.width() / 2), 1);
  EXPECT_GE(ColouredPixelsInColumn(second, second.width() / 2), ColouredPixelsInColumn(first, first.width() / 2) + 1);
}

TEST(MetricPlotTest, NothingToPlotIsAnError) {
  TempFolder dir;
  EXPECT_THROW(MetricPlot::Render({}, "run", dir / "x.png", RenderFormat::kPng), std::invalid_argument);
  EXPECT_THROW(MetricPlot::Render({MetricSeries{"empty", {}, {}, ""}}, "run", dir / "x.png", RenderFormat::kPng),
               std::invalid_argument);
  EXPECT_TRUE(dir.Files().empty());
}

TEST(MetricPlotTest, ASinglePointAndAFlatSeriesStillPlot) {
  TempFolder dir;
  MetricSeries flat{"flat", {{0, 2.0}, {100, 2.0}}, {}, ""};
  MetricSeries single{"single", {{50, 1.0}}, {}, ""};
  MetricPlot::Render({flat, single}, "run", dir / "edge.svg", RenderFormat::kSvg);
  EXPECT_EQ(dir.Files(), std::vector<std::string>{"edge.svg"});
}

}  // namespace
}  // namespace dream::render
