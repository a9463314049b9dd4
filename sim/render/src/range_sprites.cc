#include "range_sprites.h"

#include <cmath>

namespace dream::render {
namespace {

constexpr int kColours = 10;  // RobotColor repeats after this many ids

int SpriteSizePx(const ArenaLayout& layout, const SensorReach& reach) {
  return 2 * static_cast<int>(std::ceil(reach.range_m * layout.scale())) + 6;
}

}  // namespace

RangeSprites::~RangeSprites() {
  for (auto& [key, sprite] : sprites_) {
    (void)key;
    cairo_surface_destroy(sprite);
  }
}

cairo_surface_t* RangeSprites::Sprite(int robot_id, size_t reach_index, const SensorReach& reach) {
  const auto key = std::make_pair(robot_id % kColours, reach_index);
  auto found = sprites_.find(key);
  if (found != sprites_.end()) return found->second;
  const int size = SpriteSizePx(layout_, reach);
  cairo_surface_t* sprite = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size, size);
  cairo_t* cr = cairo_create(sprite);
  // The world origin lands in the sprite's centre.
  cairo_translate(cr, size / 2.0 - layout_.px(0.0), size / 2.0 - layout_.py(0.0));
  ArenaPainter(cr, layout_).SensorRange(robot_id, 0.0, 0.0, 0.0, reach, /*tint=*/false);
  cairo_destroy(cr);
  sprites_.emplace(key, sprite);
  return sprite;
}

void RangeSprites::Draw(cairo_t* cr, const ArenaOverlays& overlays, const robot_poses_t& poses) {
  if (!overlays.draw_sensor_ranges) return;
  const ArenaPainter painter(cr, layout_);
  cairo_save(cr);
  painter.ClipToArena();
  for (int32_t i = 0; i < poses.num_robots; ++i) {
    const auto k = static_cast<size_t>(i);
    for (size_t r = 0; r < overlays.sensor_reaches.size(); ++r) {
      const SensorReach& reach = overlays.sensor_reaches[r];
      if (reach.field_of_view_rad < 2 * M_PI - 1e-9) {
        painter.SensorRange(i, poses.x[k], poses.y[k], poses.theta[k], reach, /*tint=*/false);
        continue;
      }
      const double half = SpriteSizePx(layout_, reach) / 2.0;
      cairo_set_source_surface(cr, Sprite(i, r, reach), std::round(layout_.px(poses.x[k]) - half),
                               std::round(layout_.py(poses.y[k]) - half));
      cairo_paint(cr);
    }
  }
  cairo_restore(cr);
}

}  // namespace dream::render
