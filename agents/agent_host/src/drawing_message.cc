#include "dream/agent_host/drawing_message.h"

#include <algorithm>
#include <limits>

namespace dream::agent_host {

using agents::Drawing;
static_assert(Drawing::kMaxShapes == drawing_t::MAX_SHAPES && Drawing::kMaxPoints == drawing_t::MAX_POINTS &&
                  Drawing::kMaxPolygonPoints == drawing_t::MAX_POLYGON_POINTS &&
                  Drawing::kMaxTextBytes == drawing_t::MAX_TEXT_BYTES &&
                  Drawing::kMaxAllTextBytes == drawing_t::MAX_ALL_TEXT_BYTES,
              "agents::Drawing's bounds must be drawing_t's (lcmtypes/dream/drawing_t.lcm)");
static_assert(static_cast<int8_t>(agents::DrawnItem::Kind::kLine) == drawing_t::LINE &&
                  static_cast<int8_t>(agents::DrawnItem::Kind::kCircle) == drawing_t::CIRCLE &&
                  static_cast<int8_t>(agents::DrawnItem::Kind::kPolygon) == drawing_t::POLYGON &&
                  static_cast<int8_t>(agents::DrawnItem::Kind::kArrow) == drawing_t::ARROW &&
                  static_cast<int8_t>(agents::DrawnItem::Kind::kText) == drawing_t::TEXT,
              "agents::DrawnItem's kinds must be drawing_t's");

drawing_t DrawingMessageOf(const Drawing& drawing) {
  drawing_t message{};
  message.clipped = static_cast<int32_t>(std::min<long>(drawing.clipped(), std::numeric_limits<int32_t>::max()));
  for (const agents::DrawnItem& item : drawing.items()) {
    message.kind.push_back(static_cast<int8_t>(item.kind));
    message.rgba.push_back(static_cast<int32_t>(item.style.rgba));
    message.width.push_back(item.style.width_m);
    message.size.push_back(item.size_m);
    message.fill.push_back(item.style.fill ? 1 : 0);
    message.point_count.push_back(static_cast<int32_t>(item.points_m.size()));
    message.text_length.push_back(static_cast<int32_t>(item.text.size()));
    for (const auto& point : item.points_m) {
      message.x.push_back(point.x());
      message.y.push_back(point.y());
    }
    message.text.insert(message.text.end(), item.text.begin(), item.text.end());
  }
  message.num_shapes = static_cast<int32_t>(message.kind.size());
  message.num_points = static_cast<int32_t>(message.x.size());
  message.num_text_bytes = static_cast<int32_t>(message.text.size());
  return message;
}

}  // namespace dream::agent_host
