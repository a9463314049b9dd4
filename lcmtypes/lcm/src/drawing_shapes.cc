#include "dream/lcm/drawing_shapes.h"

#include <cmath>
#include <cstddef>

#include "dream/drawing_t.hpp"
#include "dream/lcm/wire_text.h"

namespace dream::lcm {
namespace {

std::string KindName(int8_t kind) {
  switch (kind) {
    case drawing_t::LINE:
      return "line";
    case drawing_t::CIRCLE:
      return "circle";
    case drawing_t::POLYGON:
      return "polygon";
    case drawing_t::ARROW:
      return "arrow";
    case drawing_t::TEXT:
      return "text";
    default:
      return "";
  }
}

// Why shape `i`'s point count does not fit its kind, or "".
std::string PointCountProblem(int8_t kind, int32_t count) {
  if (kind == drawing_t::POLYGON) {
    if (count >= 3 && count <= drawing_t::MAX_POLYGON_POINTS) return "";
    return "a polygon needs 3 to " + std::to_string(drawing_t::MAX_POLYGON_POINTS) + " points, got " +
           std::to_string(count);
  }
  const int32_t wanted = (kind == drawing_t::LINE || kind == drawing_t::ARROW) ? 2 : 1;
  if (count == wanted) return "";
  return "a " + KindName(kind) + " has " + std::to_string(wanted) + " point(s), got " + std::to_string(count);
}

bool InRange(double value, double low, double high) { return std::isfinite(value) && value >= low && value <= high; }

// Why shape `i` (its kind, style and counts) is none, or "".
std::string ShapeProblem(const drawing_t& drawing, size_t i) {
  const int8_t kind = drawing.kind[i];
  if (KindName(kind).empty()) return "kind " + std::to_string(kind) + " is none of LINE..TEXT (1..5)";
  if (std::string problem = PointCountProblem(kind, drawing.point_count[i]); !problem.empty()) return problem;
  if (!InRange(drawing.width[i], 0, DrawingShapes::kMaxSizeM) ||
      !InRange(drawing.size[i], 0, DrawingShapes::kMaxSizeM)) {
    return "width and size must be 0 to 10 m";
  }
  if (drawing.fill[i] != 0 && drawing.fill[i] != 1) return "fill must be 0 or 1";
  const int32_t text = drawing.text_length[i];
  if (kind == drawing_t::TEXT ? (text < 0 || text > drawing_t::MAX_TEXT_BYTES) : text != 0) {
    return "text_length " + std::to_string(text) + " (a text has 0 to " + std::to_string(drawing_t::MAX_TEXT_BYTES) +
           " bytes, another shape none)";
  }
  return "";
}

std::string CountsProblem(const drawing_t& drawing) {
  const auto shapes = static_cast<size_t>(drawing.num_shapes);
  if (drawing.num_shapes < 0 || drawing.kind.size() != shapes || drawing.rgba.size() != shapes ||
      drawing.width.size() != shapes || drawing.size.size() != shapes || drawing.fill.size() != shapes ||
      drawing.point_count.size() != shapes || drawing.text_length.size() != shapes || drawing.num_points < 0 ||
      drawing.x.size() != static_cast<size_t>(drawing.num_points) ||
      drawing.y.size() != static_cast<size_t>(drawing.num_points) || drawing.num_text_bytes < 0 ||
      drawing.text.size() != static_cast<size_t>(drawing.num_text_bytes)) {
    return "array sizes do not match their counts";
  }
  if (drawing.clipped < 0) return "clipped is negative (" + std::to_string(drawing.clipped) + ")";
  return "";
}

}  // namespace

std::string DrawingShapes::Problem(const drawing_t& drawing) {
  if (std::string problem = CountsProblem(drawing); !problem.empty()) return problem;
  int64_t points = 0;
  int64_t text_bytes = 0;
  for (size_t i = 0; i < drawing.kind.size(); ++i) {
    if (std::string problem = ShapeProblem(drawing, i); !problem.empty()) {
      return "shape " + std::to_string(i) + ": " + problem;
    }
    points += drawing.point_count[i];
    text_bytes += drawing.text_length[i];
  }
  if (points != drawing.num_points || text_bytes != drawing.num_text_bytes) {
    return "the shapes have " + std::to_string(points) + " points and " + std::to_string(text_bytes) +
           " text bytes, the message " + std::to_string(drawing.num_points) + " and " +
           std::to_string(drawing.num_text_bytes);
  }
  for (size_t p = 0; p < drawing.x.size(); ++p) {
    if (!InRange(drawing.x[p], -kMaxAbsCoordinateM, kMaxAbsCoordinateM) ||
        !InRange(drawing.y[p], -kMaxAbsCoordinateM, kMaxAbsCoordinateM)) {
      return "point " + std::to_string(p) + " is not finite or past 100 m";
    }
  }
  const auto* bytes = reinterpret_cast<const uint8_t*>(drawing.text.data());
  if (const int64_t bad = WireText::FirstNonUtf8Byte(bytes, drawing.num_text_bytes); bad >= 0) {
    return "text byte " + std::to_string(bad) + " is not UTF-8";
  }
  for (const uint8_t byte : drawing.text) {
    if (byte < 0x20 || byte == 0x7f) return "text holds a control character (" + std::to_string(byte) + ")";
  }
  return "";
}

std::vector<DrawnShape> DrawingShapes::Of(const drawing_t& drawing) {
  std::vector<DrawnShape> shapes;
  if (!Problem(drawing).empty()) return shapes;
  shapes.reserve(drawing.kind.size());
  size_t point = 0;
  size_t text = 0;
  for (size_t i = 0; i < drawing.kind.size(); ++i) {
    DrawnShape shape;
    shape.kind = drawing.kind[i];
    shape.rgba = static_cast<uint32_t>(drawing.rgba[i]);
    shape.width_m = drawing.width[i];
    shape.size_m = drawing.size[i];
    shape.fill = drawing.fill[i] == 1;
    const auto count = static_cast<size_t>(drawing.point_count[i]);
    shape.x_m.assign(drawing.x.begin() + static_cast<ptrdiff_t>(point),
                     drawing.x.begin() + static_cast<ptrdiff_t>(point + count));
    shape.y_m.assign(drawing.y.begin() + static_cast<ptrdiff_t>(point),
                     drawing.y.begin() + static_cast<ptrdiff_t>(point + count));
    point += count;
    const auto length = static_cast<size_t>(drawing.text_length[i]);
    shape.text.assign(reinterpret_cast<const char*>(drawing.text.data()) + text, length);
    text += length;
    shapes.push_back(std::move(shape));
  }
  return shapes;
}

}  // namespace dream::lcm
