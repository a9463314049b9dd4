#pragma once

#include <array>
#include <string>
#include <vector>

#include "dream/render/render_format.h"

namespace dream::render {

/// One data set of a panel: a line, dots or a histogram's bars.
struct XySeries {
  enum class Style { kLine, kDashedLine, kDots, kBars };
  std::string label;                          ///< in the panel's legend
  std::vector<std::array<double, 2>> points;  ///< {x, y}; bars: {bin centre, count}
  Style style = Style::kLine;
  int color = 0;  ///< the robot palette's colour index
};

/// One panel: a title, axis names and its series on shared axes.
struct XyPanel {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<XySeries> series;
};

/// Panels of x-y data in a grid (e.g. dream calibrate's real-against-fitted
/// picture), as a PNG or SVG, written atomically.
class XyPlot {
 public:
  /// @throws std::invalid_argument when there are no panels or a panel has
  ///         no points; std::runtime_error naming the path when it cannot be written.
  static void Render(const std::vector<XyPanel>& panels, int columns, const std::string& title, const std::string& path,
                     RenderFormat format, int width_px = 1200);
};

}  // namespace dream::render
