#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace dream::agents {

/// How a shape is drawn. Colours are 0xRRGGBBAA; widths and heights are
/// metres in the world, so a drawing scales with the arena.
struct DrawStyle {
  uint32_t rgba = 0x202020ffu;  ///< near black, opaque
  double width_m = 0.01;        ///< line width; 0: the thinnest line a viewer draws
  bool fill = false;            ///< circles and polygons: filled with the colour
};

/// One shape a controller drew, in world coordinates.
struct DrawnItem {
  enum class Kind : int8_t { kLine = 1, kCircle = 2, kPolygon = 3, kArrow = 4, kText = 5 };
  Kind kind = Kind::kLine;
  std::vector<Eigen::Vector2d> points_m;  ///< line, arrow: from, to; circle: centre; text: anchor; polygon: corners
  double size_m = 0;                      ///< circle: radius; text: height
  DrawStyle style;
  std::string text;  ///< text: UTF-8, printable

  bool operator==(const DrawnItem& other) const;
  bool operator!=(const DrawnItem& other) const { return !(*this == other); }
};

/// What a robot's controller drew for one step: lines, circles, polygons,
/// arrows and text in world coordinates, which `dream view` and `dream
/// render` show and the world never reads (drawing cannot change a run).
///
/// Bounded, because a controller is code we did not write: past the bounds
/// below a shape is left out, a polygon cut to its first kMaxPolygonPoints
/// corners, a text cut to kMaxTextBytes (between characters); a shape with a
/// coordinate that is not finite or past kMaxAbsCoordinateM, or a size past
/// kMaxSizeM, is left out; a text's bytes that are not printable UTF-8 become
/// '?'. Each is counted with its reason (clipped(), clip_reasons()). The
/// bounds are drawing_t's (lcmtypes/dream/drawing_t.lcm), which the agent
/// host checks are these.
class Drawing {
 public:
  static constexpr int kMaxShapes = 64;
  static constexpr int kMaxPolygonPoints = 64;
  static constexpr int kMaxPoints = 1024;
  static constexpr int kMaxTextBytes = 96;
  static constexpr int kMaxAllTextBytes = 2048;
  static constexpr double kMaxAbsCoordinateM = 100.0;
  static constexpr double kMaxSizeM = 10.0;

  void Line(const Eigen::Vector2d& from_m, const Eigen::Vector2d& to_m, const DrawStyle& style = {});
  /// An arrow from `from_m` to `to_m`, its head at `to_m`.
  void Arrow(const Eigen::Vector2d& from_m, const Eigen::Vector2d& to_m, const DrawStyle& style = {});
  void Circle(const Eigen::Vector2d& centre_m, double radius_m, const DrawStyle& style = {});
  /// A closed polygon through `corners_m` (3 or more).
  void Polygon(const std::vector<Eigen::Vector2d>& corners_m, const DrawStyle& style = {});
  /// `text` with its lower left corner at `anchor_m`, `height_m` tall.
  void Text(const Eigen::Vector2d& anchor_m, const std::string& text, double height_m = 0.06,
            const DrawStyle& style = {});

  const std::vector<DrawnItem>& items() const { return items_; }
  bool empty() const { return items_.empty(); }
  /// Shapes, points and text bytes left out or cut, summed.
  long clipped() const { return clipped_; }
  /// The same by reason ("more than 64 shapes in one step", ...).
  const std::map<std::string, long>& clip_reasons() const { return clip_reasons_; }

  /// The same shapes (what was clipped aside).
  bool SameShapes(const Drawing& other) const { return items_ == other.items_; }

 private:
  void Add(DrawnItem item);
  void Clip(const std::string& reason, long amount);
  /// `text` cut to what fits (kMaxTextBytes and what is left of kMaxAllTextBytes) and made printable UTF-8.
  std::string Bounded(const std::string& text);

  std::vector<DrawnItem> items_;
  int points_ = 0;
  int text_bytes_ = 0;
  long clipped_ = 0;
  std::map<std::string, long> clip_reasons_;
};

}  // namespace dream::agents
