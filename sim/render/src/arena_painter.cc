#include "arena_painter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <unordered_set>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/run_verdict.h"
#include "drawing_painter.h"
#include "violation_painter.h"

namespace dream::render {
namespace {

constexpr std::array<std::array<double, 3>, 10> kColors = {{{0.12, 0.47, 0.71},
                                                            {1.00, 0.50, 0.05},
                                                            {0.17, 0.63, 0.17},
                                                            {0.84, 0.15, 0.16},
                                                            {0.58, 0.40, 0.74},
                                                            {0.55, 0.34, 0.29},
                                                            {0.89, 0.47, 0.76},
                                                            {0.50, 0.50, 0.50},
                                                            {0.74, 0.74, 0.13},
                                                            {0.09, 0.75, 0.81}}};

constexpr double kRobotRadiusM = robotarium::RobotariumConstants::kRobotDiameterMeters / 2;

// "-1.5", "0", "1": a grid line's position in metres.
std::string TickLabel(double value_m) {
  char text[16];
  std::snprintf(text, sizeof(text), "%g", std::abs(value_m) < 1e-9 ? 0.0 : value_m);
  return text;
}

// Positions k * step_m from lo_m to hi_m (counted, so 0.1 steps do not drift).
std::vector<double> GridLines(double lo_m, double hi_m, double step_m) {
  std::vector<double> lines;
  const auto first = static_cast<int64_t>(std::ceil(lo_m / step_m - 1e-9));
  const auto last = static_cast<int64_t>(std::floor(hi_m / step_m + 1e-9));
  for (int64_t k = first; k <= last; ++k) lines.push_back(static_cast<double>(k) * step_m);
  return lines;
}

// Null for a verdict of no known name (shown as it is).
const char* VerdictExplained(const std::string& verdict) {
  const std::optional<world::RunVerdict> known = world::ParseRunVerdict(verdict);
  if (!known) return nullptr;
  switch (*known) {
    case world::RunVerdict::kClean:
      return "clean (no errors or warnings)";
    case world::RunVerdict::kWarning:
      return "warning (accepted: actuator limits only)";
    case world::RunVerdict::kNotReady:
      return "not ready (robots lost, conflicts, bad messages or goal missed)";
    case world::RunVerdict::kRejected:
      return "rejected (boundary, collision or obstacle errors)";
  }
  return nullptr;
}

}  // namespace

std::string RunLabel(const ArenaOverlays& overlays, bool short_verdict) {
  std::string label;
  if (!overlays.run_name.empty()) label += overlays.run_name + " \xe2\x80\x94 ";
  if (!overlays.verdict.empty()) {
    const char* explained = short_verdict ? nullptr : VerdictExplained(overlays.verdict);
    label += (explained != nullptr ? std::string(explained) : overlays.verdict) + " \xe2\x80\x94 ";
  }
  if (overlays.sim_only) label += "sim-only run (never to the lab) \xe2\x80\x94 ";
  return label;
}

const std::array<double, 3>& RobotColor(int robot_id) {
  return kColors[static_cast<size_t>(robot_id < 0 ? 0 : robot_id) % kColors.size()];
}

void ArenaPainter::SetColor(int robot_id, double alpha) const {
  const auto& rgb = RobotColor(robot_id);
  cairo_set_source_rgba(cr_, rgb[0], rgb[1], rgb[2], alpha);
}

void ArenaPainter::Background() const {
  const world::Arena& arena = layout_.arena();
  const double ui = layout_.ui_scale();
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
  cairo_save(cr_);
  if (layout_.zoomed()) {
    // A viewport: only the frame shows the world; its edge is drawn, thin.
    cairo_set_source_rgb(cr_, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr_, 1.0);
    cairo_rectangle(cr_, layout_.frame_left_px() - 0.5, layout_.frame_top_px() - 0.5,
                    layout_.frame_right_px() - layout_.frame_left_px() + 1,
                    layout_.frame_bottom_px() - layout_.frame_top_px() + 1);
    cairo_stroke(cr_);
    cairo_rectangle(cr_, layout_.frame_left_px(), layout_.frame_top_px(),
                    layout_.frame_right_px() - layout_.frame_left_px(),
                    layout_.frame_bottom_px() - layout_.frame_top_px());
    cairo_clip(cr_);
  }
  cairo_set_source_rgb(cr_, 0.9, 0.9, 0.9);
  cairo_set_line_width(cr_, std::max(1.0, ui));
  const double step = layout_.grid_step_m();
  for (const double x : GridLines(arena.x_min_m, arena.x_max_m, step)) {
    cairo_move_to(cr_, layout_.px(x), layout_.py(arena.y_min_m));
    cairo_line_to(cr_, layout_.px(x), layout_.py(arena.y_max_m));
  }
  for (const double y : GridLines(arena.y_min_m, arena.y_max_m, step)) {
    cairo_move_to(cr_, layout_.px(arena.x_min_m), layout_.py(y));
    cairo_line_to(cr_, layout_.px(arena.x_max_m), layout_.py(y));
  }
  cairo_stroke(cr_);
  cairo_set_source_rgb(cr_, 0, 0, 0);
  cairo_set_line_width(cr_, std::max(1.0, 2.0 * ui));
  cairo_rectangle(cr_, layout_.px(arena.x_min_m), layout_.py(arena.y_max_m), arena.width_m() * layout_.scale(),
                  arena.height_m() * layout_.scale());
  cairo_stroke(cr_);
  cairo_restore(cr_);
  AxisLabels();
}

void ArenaPainter::AxisLabels() const {
  const double ui = std::max(layout_.ui_scale(), 0.5);
  const double gap = 5.0 * ui;  // between the frame and a label
  cairo_set_source_rgb(cr_, 0.45, 0.45, 0.45);
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, layout_.tick_font_px());
  cairo_font_extents_t font;
  cairo_font_extents(cr_, &font);
  cairo_text_extents_t extents;
  // x: centred under each grid line; the unit after the frame's right end.
  const Viewport& seen = layout_.visible();
  const double step = layout_.grid_step_m();
  const double x_baseline = layout_.frame_bottom_px() + gap + font.ascent;
  for (const double x : GridLines(seen.x_min_m, seen.x_max_m, step)) {
    const std::string text = TickLabel(x);
    cairo_text_extents(cr_, text.c_str(), &extents);
    cairo_move_to(cr_, layout_.px(x) - extents.x_advance / 2, x_baseline);
    cairo_show_text(cr_, text.c_str());
  }
  cairo_move_to(cr_, layout_.frame_right_px() + gap, x_baseline);
  cairo_show_text(cr_, "m");
  // y: right-aligned left of the frame, vertically centred on each grid line.
  const double middle = (font.ascent - font.descent) / 2;
  for (const double y : GridLines(seen.y_min_m, seen.y_max_m, step)) {
    const std::string text = TickLabel(y);
    cairo_text_extents(cr_, text.c_str(), &extents);
    cairo_move_to(cr_, layout_.frame_left_px() - gap - extents.x_advance, layout_.py(y) + middle);
    cairo_show_text(cr_, text.c_str());
  }
}

void ArenaPainter::Legend(const std::vector<LegendItem>& items) const {
  const double y = layout_.legend_center_px();
  const double font_px = layout_.caption_font_px() * 0.9;
  const double ui = std::max(layout_.ui_scale(), 0.5);
  const double marker_px = kRobotRadiusM * layout_.frame_scale();  // half the widest marker
  double x = layout_.frame_left_px() + marker_px;
  for (const LegendItem& item : items) {
    switch (item.marker) {
      case LegendItem::Marker::kRobot:
        RobotAtPixel(0, x, y, 0.0, item.look, false, marker_px * item.size_factor);
        break;
      case LegendItem::Marker::kGoal:
        GoalAtPixel(0, x, y, true);
        break;
      case LegendItem::Marker::kObstacle:
        cairo_set_source_rgb(cr_, 0.25, 0.25, 0.25);
        cairo_rectangle(cr_, x - marker_px * 0.8, y - marker_px * 0.8, marker_px * 1.6, marker_px * 1.6);
        cairo_fill(cr_);
        break;
      case LegendItem::Marker::kViolation:
        ViolationRing(cr_, x, y, marker_px, std::max(1.5, 2.0 * ui), 1.0);
        break;
    }
    // A filled robot's heading tick reaches 1.5 radii from its centre.
    const double label_x = x + 1.5 * marker_px + 8.0 * ui;
    cairo_set_source_rgb(cr_, 0.3, 0.3, 0.3);
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr_, font_px);
    cairo_font_extents_t font;
    cairo_font_extents(cr_, &font);
    cairo_text_extents_t extents;
    cairo_text_extents(cr_, item.label.c_str(), &extents);
    cairo_move_to(cr_, label_x, y + (font.ascent - font.descent) / 2);
    cairo_show_text(cr_, item.label.c_str());
    x = label_x + extents.x_advance + 24.0 * ui + marker_px;
  }
}

void ArenaPainter::Drawings(const ArenaOverlays& overlays, const run_log::RunLog& log, int64_t step) const {
  if (!overlays.draw_drawings || log.drawings().empty()) return;
  cairo_save(cr_);
  ClipToArena();
  DrawingPainter(cr_, layout_).Paint(run_log::DrawingsShownAt(log.drawings(), step));
  cairo_restore(cr_);
}

void ArenaPainter::ClipToArena() const {
  const world::Arena& arena = layout_.arena();
  // Zoomed, the arena may reach past the frame: the frame bounds it.
  const double left = std::floor(std::max(layout_.px(arena.x_min_m), layout_.frame_left_px()));
  const double top = std::floor(std::max(layout_.py(arena.y_max_m), layout_.frame_top_px()));
  const double right = std::ceil(std::min(layout_.px(arena.x_max_m), layout_.frame_right_px()));
  const double bottom = std::ceil(std::min(layout_.py(arena.y_min_m), layout_.frame_bottom_px()));
  cairo_rectangle(cr_, left, top, std::max(0.0, right - left), std::max(0.0, bottom - top));
  cairo_clip(cr_);
}

void ArenaPainter::Obstacles(const std::vector<rectangle_obstacle_t>& obstacles) const {
  cairo_set_source_rgb(cr_, 0.25, 0.25, 0.25);
  for (const rectangle_obstacle_t& o : obstacles) {
    cairo_rectangle(cr_, layout_.px(o.center_x - o.width / 2), layout_.py(o.center_y + o.height / 2),
                    o.width * layout_.scale(), o.height * layout_.scale());
  }
  cairo_fill(cr_);
}

void ArenaPainter::ObstaclePaths(const std::vector<std::vector<std::array<double, 2>>>& paths_m) const {
  const double dash = 6.0 * std::max(layout_.ui_scale(), 0.5);
  cairo_set_dash(cr_, &dash, 1, 0);
  cairo_set_source_rgba(cr_, 0.4, 0.4, 0.4, 0.6);
  cairo_set_line_width(cr_, std::max(1.0, layout_.ui_scale()));
  for (const auto& path : paths_m) {
    for (size_t i = 0; i < path.size(); ++i) {
      if (i == 0) cairo_move_to(cr_, layout_.px(path[i][0]), layout_.py(path[i][1]));
      cairo_line_to(cr_, layout_.px(path[i][0]), layout_.py(path[i][1]));
    }
    cairo_stroke(cr_);
  }
  cairo_set_dash(cr_, nullptr, 0, 0);
}

void ArenaPainter::Goals(const std::vector<std::vector<std::array<double, 2>>>& goals_m) const {
  for (size_t robot = 0; robot < goals_m.size(); ++robot) {
    const auto& goals = goals_m[robot];
    for (size_t g = 0; g < goals.size(); ++g) {
      GoalAtPixel(static_cast<int>(robot), layout_.px(goals[g][0]), layout_.py(goals[g][1]), g + 1 == goals.size());
    }
  }
}

void ArenaPainter::GoalAtPixel(int robot_id, double x, double y, bool last) const {
  const double arm = kRobotRadiusM * 0.6 * layout_.scale();
  SetColor(robot_id, last ? 1.0 : 0.5);
  cairo_set_line_width(cr_, std::max(1.0, (last ? 2.5 : 1.5) * layout_.ui_scale()));
  cairo_move_to(cr_, x - arm, y - arm);
  cairo_line_to(cr_, x + arm, y + arm);
  cairo_move_to(cr_, x - arm, y + arm);
  cairo_line_to(cr_, x + arm, y - arm);
  cairo_stroke(cr_);
}

void ArenaPainter::Track(int robot_id, const std::vector<std::array<double, 2>>& points_m, double line_width_px,
                         double alpha, bool dashed) const {
  if (points_m.empty()) return;
  SetColor(robot_id, alpha);
  cairo_set_line_width(cr_, std::max(1.0, line_width_px * layout_.ui_scale()));
  const double dash[] = {7.0 * layout_.ui_scale(), 4.0 * layout_.ui_scale()};
  if (dashed) cairo_set_dash(cr_, dash, 2, 0);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  // A segment is known by its pixel-rounded ends, so a robot that drives the
  // same lap 100 times costs one lap.
  auto key = [](const std::array<double, 2>& a, const std::array<double, 2>& b) {
    auto pixel = [](double v) { return static_cast<uint64_t>(static_cast<uint16_t>(std::lround(v) + 16384)); };
    uint64_t from = pixel(a[0]) << 16 | pixel(a[1]);
    uint64_t to = pixel(b[0]) << 16 | pixel(b[1]);
    if (from > to) std::swap(from, to);
    return from << 32 | to;
  };
  std::unordered_set<uint64_t> drawn;
  std::array<double, 2> last = {layout_.px(points_m.front()[0]), layout_.py(points_m.front()[1])};
  bool pen_down = false;
  for (size_t i = 1; i < points_m.size(); ++i) {
    const std::array<double, 2> point = {layout_.px(points_m[i][0]), layout_.py(points_m[i][1])};
    const double dx = point[0] - last[0];
    const double dy = point[1] - last[1];
    if (dx * dx + dy * dy < 1.0 && i + 1 < points_m.size()) continue;
    if (drawn.insert(key(last, point)).second) {
      if (!pen_down) cairo_move_to(cr_, last[0], last[1]);
      cairo_line_to(cr_, point[0], point[1]);
      pen_down = true;
    } else {
      pen_down = false;
    }
    last = point;
  }
  cairo_stroke(cr_);
  if (dashed) cairo_set_dash(cr_, nullptr, 0, 0);
}

void ArenaPainter::Robot(int robot_id, double x_m, double y_m, double theta_rad, RobotLook look, bool label,
                         double size_factor) const {
  RobotAtPixel(robot_id, layout_.px(x_m), layout_.py(y_m), theta_rad, look, label,
               kRobotRadiusM * layout_.scale() * size_factor);
}

void ArenaPainter::RobotAtPixel(int robot_id, double x, double y, double theta_rad, RobotLook look, bool label,
                                double radius_px) const {
  SetColor(robot_id, 1.0);
  cairo_new_path(cr_);
  cairo_arc(cr_, x, y, radius_px, 0, 2 * M_PI);
  if (look == RobotLook::kHollow) {
    cairo_set_line_width(cr_, std::max(1.0, 1.5 * layout_.ui_scale()));
    cairo_stroke(cr_);
    return;
  }
  cairo_fill(cr_);
  // Heading: a tick from the centre to just past the rim, in the direction of travel.
  cairo_set_source_rgb(cr_, 0, 0, 0);
  cairo_set_line_width(cr_, std::max(1.0, 2.0 * layout_.ui_scale()));
  cairo_move_to(cr_, x, y);
  cairo_line_to(cr_, x + 1.5 * radius_px * std::cos(theta_rad), y - 1.5 * radius_px * std::sin(theta_rad));
  cairo_stroke(cr_);
  if (!label) return;
  const std::string text = std::to_string(robot_id);
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr_, radius_px * 0.95);
  cairo_text_extents_t extents;
  cairo_text_extents(cr_, text.c_str(), &extents);
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_move_to(cr_, x - extents.width / 2 - extents.x_bearing, y - extents.height / 2 - extents.y_bearing);
  cairo_show_text(cr_, text.c_str());
}

void ArenaPainter::SensorRange(int robot_id, double x_m, double y_m, double theta_rad, const SensorReach& reach,
                               bool tint) const {
  const double x = layout_.px(x_m);
  const double y = layout_.py(y_m);
  const double radius_px = reach.range_m * layout_.scale();
  cairo_new_path(cr_);
  if (reach.field_of_view_rad >= 2 * M_PI - 1e-9) {
    cairo_arc(cr_, x, y, radius_px, 0, 2 * M_PI);
  } else {
    // Picture y points down, so world angles turn the other way.
    const double centre = -(theta_rad + reach.direction_rad);
    cairo_move_to(cr_, x, y);
    cairo_arc(cr_, x, y, radius_px, centre - reach.field_of_view_rad / 2, centre + reach.field_of_view_rad / 2);
    cairo_close_path(cr_);
  }
  if (tint) {
    SetColor(robot_id, 0.05);
    cairo_fill_preserve(cr_);
  }
  SetColor(robot_id, 0.4);
  cairo_set_line_width(cr_, std::max(1.0, layout_.ui_scale()));
  cairo_stroke(cr_);
}

void ArenaPainter::SensorRanges(const ArenaOverlays& overlays, const robot_poses_t& poses, bool tint) const {
  if (!overlays.draw_sensor_ranges) return;
  // Ranges reach past the walls; drawn only inside the arena they stay readable.
  cairo_save(cr_);
  ClipToArena();
  for (int32_t i = 0; i < poses.num_robots; ++i) {
    const auto k = static_cast<size_t>(i);
    for (const SensorReach& reach : overlays.sensor_reaches) {
      SensorRange(i, poses.x[k], poses.y[k], poses.theta[k], reach, tint);
    }
  }
  cairo_restore(cr_);
}

void ArenaPainter::RadioLinks(const ArenaOverlays& overlays, const run_log::RunLog& log, size_t pose_index,
                              int64_t window_steps) const {
  if (!overlays.draw_radio_links || !overlays.hears) return;
  const robot_poses_t& poses = log.poses()[pose_index];
  const int n = poses.num_robots;
  if (window_steps <= 0 || log.radio_sends().empty()) {
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (!overlays.hears(i, j, poses) && !overlays.hears(j, i, poses)) continue;
        RadioLink(poses.x[static_cast<size_t>(i)], poses.y[static_cast<size_t>(i)], poses.x[static_cast<size_t>(j)],
                  poses.y[static_cast<size_t>(j)], 0.25);
      }
    }
    return;
  }
  const auto& sends = log.radio_sends();
  const int64_t now = poses.step;
  auto send = std::lower_bound(sends.begin(), sends.end(), now - window_steps + 1,
                               [](const run_log::RadioSend& s, int64_t step) { return s.step < step; });
  for (; send != sends.end() && send->step <= now; ++send) {
    const int sender = send->sender_id;
    if (sender < 0 || sender >= n) continue;
    const double alpha = 0.8 * (1.0 - static_cast<double>(now - send->step) / static_cast<double>(window_steps));
    const auto s = static_cast<size_t>(sender);
    for (int receiver = 0; receiver < n; ++receiver) {
      if (receiver == sender || !overlays.hears(receiver, sender, poses)) continue;
      const auto r = static_cast<size_t>(receiver);
      RadioLink(poses.x[s], poses.y[s], poses.x[r], poses.y[r], alpha);
    }
  }
}

void ArenaPainter::RadioLink(double x0_m, double y0_m, double x1_m, double y1_m, double alpha) const {
  cairo_set_source_rgba(cr_, 0.1, 0.1, 0.1, alpha);
  cairo_set_line_width(cr_, std::max(1.0, 1.5 * layout_.ui_scale()));
  cairo_move_to(cr_, layout_.px(x0_m), layout_.py(y0_m));
  cairo_line_to(cr_, layout_.px(x1_m), layout_.py(y1_m));
  cairo_stroke(cr_);
}

void ArenaPainter::Caption(int line, const std::string& text) const {
  cairo_set_source_rgb(cr_, 0.2, 0.2, 0.2);
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr_, layout_.caption_font_px());
  cairo_move_to(cr_, layout_.frame_left_px(), layout_.caption_baseline_px(line));
  cairo_show_text(cr_, text.c_str());
}

}  // namespace dream::render
