#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "dream/render/render_format.h"

namespace dream::render {

/// One quantity of a run over time, e.g. summary.json's metrics.coverage_cost.
struct MetricSeries {
  std::string name;
  std::vector<std::array<double, 2>> points;  ///< {step, value}, in step order
  std::optional<double> limit;                ///< a dashed red reference line, e.g. the collision distance
  std::string limit_label;
};

/// Plots of a run's metrics over time: one panel per series, stacked, sharing
/// a time axis in simulated seconds (step x 0.033 s), each with its own value
/// axis, as a PNG or SVG.
class MetricPlot {
 public:
  /// @throws std::invalid_argument when `series` is empty or a series has no points;
  ///         std::runtime_error naming the path when it cannot be written.
  static void Render(const std::vector<MetricSeries>& series, const std::string& title, const std::string& path,
                     RenderFormat format, int width_px = 1000);
};

}  // namespace dream::render
