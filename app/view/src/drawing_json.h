#pragma once

#include <vector>

#include "dream/lcm/drawn_shape.h"
#include "json_writer.h"

namespace dream::view {

/// A controller's shapes (DREAM_DRAW_<id>) as the page draws them
/// (arena.js, drawShapes): an array of [kind, rgba, width, size, fill,
/// [x...], [y...], text] (metres; kind drawing_t::LINE..TEXT; rgba 0xRRGGBBAA).
void AppendShapes(JsonWriter& json, const std::vector<lcm::DrawnShape>& shapes);

}  // namespace dream::view
