#pragma once

#include <cairo.h>

#include <array>
#include <string>
#include <vector>

#include "dream/rectangle_obstacle_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/render/arena_layout.h"
#include "dream/render/arena_overlays.h"
#include "dream/run_log/run_log.h"

namespace dream::render {

/// Matplotlib's tab10, so pictures look like the Robotarium's own plots.
const std::array<double, 3>& RobotColor(int robot_id);

/// Draws the pieces of an arena picture in world coordinates on any cairo
/// context (PNG, SVG or a video frame): the one drawing code behind
/// TrajectoryPicture, ComparisonPicture and RunAnimation.
class ArenaPainter {
 public:
  /// How a robot is drawn: a disc of the robot's 0.11 m diameter.
  enum class RobotLook {
    kFilled,  ///< filled in its colour, black heading tick (final or current pose)
    kHollow,  ///< outline in its colour (a start pose, or the planned run in a comparison)
  };

  /// A marker of the legend row, drawn by the same code as in the arena.
  struct LegendItem {
    enum class Marker {
      kRobot,      ///< a robot disc (robot 0's colour) with `look` and `size_factor`, heading right
      kGoal,       ///< a goal cross (robot 0's colour, as a last goal)
      kObstacle,   ///< a dark grey square, as obstacles are filled
      kViolation,  ///< a violation's red ring with a cross (ViolationRing)
    };
    Marker marker;
    std::string label;
    RobotLook look = RobotLook::kFilled;
    double size_factor = 1.0;
  };

  ArenaPainter(cairo_t* cr, const ArenaLayout& layout) : cr_(cr), layout_(layout) {}

  /// White, a half-metre grid, the arena boundary and, outside it, the grid
  /// lines' positions in metres (x below, y on the left).
  void Background() const;
  /// Small grey tick labels in metres at the half-metre grid lines, outside
  /// the arena frame (part of Background()).
  void AxisLabels() const;
  /// The legend row between the arena and the captions: each item's marker
  /// and its label, left to right.
  void Legend(const std::vector<LegendItem>& items) const;
  /// Limits drawing to the arena (on whole pixels: a cheap rectangle, not a
  /// mask); wrap in cairo_save/cairo_restore.
  void ClipToArena() const;
  /// The rectangles, filled dark grey.
  void Obstacles(const std::vector<rectangle_obstacle_t>& obstacles) const;
  /// Dashed grey centre paths of moving obstacles.
  void ObstaclePaths(const std::vector<std::vector<std::array<double, 2>>>& paths_m) const;
  /// Each robot's goals: a cross in its colour (the last goal bolder).
  void Goals(const std::vector<std::vector<std::array<double, 2>>>& goals_m) const;
  /// A robot's path through `points_m` in its colour. Cheap for long runs:
  /// points closer than a pixel to the last kept one are dropped, and a
  /// pixel-rounded segment already drawn is not drawn again.
  void Track(int robot_id, const std::vector<std::array<double, 2>>& points_m, double line_width_px, double alpha = 1.0,
             bool dashed = false) const;
  /// A robot at (x, y) heading `theta`, to scale, optionally with its id.
  void Robot(int robot_id, double x_m, double y_m, double theta_rad, RobotLook look, bool label = false,
             double size_factor = 1.0) const;
  /// A sensor's reach round a robot: the outline of a disc (or wedge) in its
  /// colour, and with `tint` a translucent fill (costly to blend in every video frame).
  void SensorRange(int robot_id, double x_m, double y_m, double theta_rad, const SensorReach& reach, bool tint) const;
  /// Every sensor reach of `overlays` round every robot at `poses`, when
  /// overlays.draw_sensor_ranges is set (see SensorRange for `tint`).
  void SensorRanges(const ArenaOverlays& overlays, const robot_poses_t& poses, bool tint) const;
  /// Radio links at log.poses()[pose_index], when overlays.draw_radio_links
  /// is set: each broadcast of the last `window_steps` steps as lines from its
  /// sender to the robots that hear it, fading with age; with window_steps 0,
  /// or a log without radio messages, every pair that can hear each other.
  void RadioLinks(const ArenaOverlays& overlays, const run_log::RunLog& log, size_t pose_index,
                  int64_t window_steps) const;
  /// A radio link from (x0, y0) to (x1, y1), with opacity `alpha`.
  void RadioLink(double x0_m, double y0_m, double x1_m, double y1_m, double alpha) const;
  /// What the controllers drew (DREAM_DRAW_<id>) shown at `step`: each
  /// robot's latest drawing then (run_log::DrawingsShownAt), clipped to the
  /// arena, when overlays.draw_drawings is set (DrawingPainter).
  void Drawings(const ArenaOverlays& overlays, const run_log::RunLog& log, int64_t step) const;
  /// Writes `text` as caption line `line` (0 = first) under the arena.
  void Caption(int line, const std::string& text) const;

 private:
  void SetColor(int robot_id, double alpha) const;
  void RobotAtPixel(int robot_id, double x, double y, double theta_rad, RobotLook look, bool label,
                    double radius_px) const;
  void GoalAtPixel(int robot_id, double x, double y, bool last) const;

  cairo_t* cr_;
  const ArenaLayout& layout_;
};

}  // namespace dream::render
