#pragma once

#include <cairo.h>

#include <map>
#include <utility>

#include "arena_painter.h"

namespace dream::render {

/// Sensor ranges for video frames, fast: a 1 m range is a ring 400 px across
/// at 720 px, and stroking ten of those costs several milliseconds a frame,
/// while copying a ring drawn once (by ArenaPainter::SensorRange) to whole
/// pixel positions costs a fifth of that. Wedges turn with their robot and are
/// drawn directly.
class RangeSprites {
 public:
  explicit RangeSprites(const ArenaLayout& layout) : layout_(layout) {}
  ~RangeSprites();
  RangeSprites(const RangeSprites&) = delete;
  RangeSprites& operator=(const RangeSprites&) = delete;

  /// The reach of every sensor of `overlays` round every robot at `poses`,
  /// inside the arena, when overlays.draw_sensor_ranges is set.
  void Draw(cairo_t* cr, const ArenaOverlays& overlays, const robot_poses_t& poses);

 private:
  cairo_surface_t* Sprite(int robot_id, size_t reach_index, const SensorReach& reach);

  const ArenaLayout& layout_;
  std::map<std::pair<int, size_t>, cairo_surface_t*> sprites_;  // by (colour, reach)
};

}  // namespace dream::render
