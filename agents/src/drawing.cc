#include "dream/agents/framework/drawing.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace dream::agents {
namespace {

bool Inside(const Eigen::Vector2d& point_m) {
  return std::isfinite(point_m.x()) && std::isfinite(point_m.y()) &&
         std::abs(point_m.x()) <= Drawing::kMaxAbsCoordinateM && std::abs(point_m.y()) <= Drawing::kMaxAbsCoordinateM;
}

bool SizeInside(double size_m) { return std::isfinite(size_m) && size_m >= 0 && size_m <= Drawing::kMaxSizeM; }

// Bytes of the UTF-8 sequence starting with `lead` (1 for a byte that starts none).
size_t SequenceBytes(unsigned char lead) {
  if (lead >= 0xC2 && lead <= 0xDF) return 2;
  if (lead >= 0xE0 && lead <= 0xEF) return 3;
  if (lead >= 0xF0 && lead <= 0xF4) return 4;
  return 1;
}

bool Continuations(const std::string& text, size_t at, size_t count) {
  if (at + count > text.size()) return false;
  for (size_t k = 1; k < count; ++k) {
    if ((static_cast<unsigned char>(text[at + k]) & 0xC0) != 0x80) return false;
  }
  // Overlong forms and surrogates are refused by the world's check (lcm::WireText): keep to what it takes.
  const auto lead = static_cast<unsigned char>(text[at]);
  const auto second = count > 1 ? static_cast<unsigned char>(text[at + 1]) : 0;
  if (lead == 0xE0 && second < 0xA0) return false;
  if (lead == 0xED && second > 0x9F) return false;
  if (lead == 0xF0 && second < 0x90) return false;
  if (lead == 0xF4 && second > 0x8F) return false;
  return true;
}

}  // namespace

bool DrawnItem::operator==(const DrawnItem& other) const {
  return kind == other.kind && points_m == other.points_m && size_m == other.size_m && style.rgba == other.style.rgba &&
         style.width_m == other.style.width_m && style.fill == other.style.fill && text == other.text;
}

void Drawing::Clip(const std::string& reason, long amount) {
  clipped_ += amount;
  clip_reasons_[reason] += amount;
}

std::string Drawing::Bounded(const std::string& text) {
  std::string printable;
  for (size_t at = 0; at < text.size();) {
    const auto lead = static_cast<unsigned char>(text[at]);
    const size_t count = SequenceBytes(lead);
    const bool control = lead < 0x20 || lead == 0x7f;
    const bool valid = lead < 0x80 ? !control : (count > 1 && Continuations(text, at, count));
    if (valid) {
      printable.append(text, at, count);
      at += count;
    } else {
      printable += '?';
      Clip("a text byte that is not printable UTF-8 (made '?')", 1);
      at += 1;
    }
  }
  const size_t room = static_cast<size_t>(std::min(kMaxTextBytes, kMaxAllTextBytes - text_bytes_));
  if (printable.size() <= room) return printable;
  size_t cut = room;
  while (cut > 0 && (static_cast<unsigned char>(printable[cut]) & 0xC0) == 0x80) --cut;  // between characters
  Clip("text bytes past " + std::to_string(kMaxTextBytes) + " in one text or " + std::to_string(kMaxAllTextBytes) +
           " in one step (cut)",
       static_cast<long>(printable.size() - cut));
  return printable.substr(0, cut);
}

void Drawing::Add(DrawnItem item) {
  if (static_cast<int>(items_.size()) >= kMaxShapes) {
    Clip("more than " + std::to_string(kMaxShapes) + " shapes in one step (left out)", 1);
    return;
  }
  for (const Eigen::Vector2d& point : item.points_m) {
    if (!Inside(point)) {
      Clip("a point that is not finite or past 100 m (shape left out)", 1);
      return;
    }
  }
  if (!SizeInside(item.size_m) || !SizeInside(item.style.width_m)) {
    Clip("a size or width that is not finite, negative or past 10 m (shape left out)", 1);
    return;
  }
  if (points_ + static_cast<int>(item.points_m.size()) > kMaxPoints) {
    Clip("more than " + std::to_string(kMaxPoints) + " points in one step (shape left out)", 1);
    return;
  }
  if (item.kind == DrawnItem::Kind::kText) {
    item.text = Bounded(item.text);
    text_bytes_ += static_cast<int>(item.text.size());
  }
  if (item.kind != DrawnItem::Kind::kCircle && item.kind != DrawnItem::Kind::kPolygon) item.style.fill = false;
  points_ += static_cast<int>(item.points_m.size());
  items_.push_back(std::move(item));
}

void Drawing::Line(const Eigen::Vector2d& from_m, const Eigen::Vector2d& to_m, const DrawStyle& style) {
  Add(DrawnItem{DrawnItem::Kind::kLine, {from_m, to_m}, 0.0, style, ""});
}

void Drawing::Arrow(const Eigen::Vector2d& from_m, const Eigen::Vector2d& to_m, const DrawStyle& style) {
  Add(DrawnItem{DrawnItem::Kind::kArrow, {from_m, to_m}, 0.0, style, ""});
}

void Drawing::Circle(const Eigen::Vector2d& centre_m, double radius_m, const DrawStyle& style) {
  Add(DrawnItem{DrawnItem::Kind::kCircle, {centre_m}, radius_m, style, ""});
}

void Drawing::Polygon(const std::vector<Eigen::Vector2d>& corners_m, const DrawStyle& style) {
  if (corners_m.size() < 3) {
    Clip("a polygon of fewer than 3 corners (left out)", 1);
    return;
  }
  std::vector<Eigen::Vector2d> kept = corners_m;
  if (kept.size() > static_cast<size_t>(kMaxPolygonPoints)) {
    Clip("polygon corners past " + std::to_string(kMaxPolygonPoints) + " (cut)",
         static_cast<long>(kept.size()) - kMaxPolygonPoints);
    kept.resize(static_cast<size_t>(kMaxPolygonPoints));
  }
  Add(DrawnItem{DrawnItem::Kind::kPolygon, std::move(kept), 0.0, style, ""});
}

void Drawing::Text(const Eigen::Vector2d& anchor_m, const std::string& text, double height_m, const DrawStyle& style) {
  Add(DrawnItem{DrawnItem::Kind::kText, {anchor_m}, height_m, style, text});
}

}  // namespace dream::agents
