#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace dream::lcm {

/// One shape of a drawing_t, as plain values (DrawingShapes::Of).
struct DrawnShape {
  int8_t kind = 0;          ///< drawing_t::LINE ... TEXT
  uint32_t rgba = 0;        ///< 0xRRGGBBAA
  double width_m = 0;       ///< line width
  double size_m = 0;        ///< CIRCLE: radius; TEXT: height
  bool fill = false;        ///< CIRCLE, POLYGON: filled
  std::vector<double> x_m;  ///< the shape's points, world frame
  std::vector<double> y_m;
  std::string text;  ///< TEXT: UTF-8
};

}  // namespace dream::lcm
