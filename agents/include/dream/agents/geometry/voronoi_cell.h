#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dream/agents/geometry/convex_polygon.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/geometry/half_plane.h"
#include "dream/agents/framework/sensor_readings.h"
#include "dream/agents/geometry/robotarium_arena.h"

namespace dream::agents {

/// How a robot's Voronoi cell is shaped.
struct VoronoiCellParams {
  double disc_radius_m = 1.0;  ///< sensing/communication limit: the cell lies in this disc; > 0
  /// The disc as an inscribed regular polygon with this many sides, 8..1024
  /// (1024 sides miss 6e-6 of the disc's area; every robot builds the polygon
  /// every step, so the bound keeps a config from asking for 2^31 vertices).
  int disc_sides = 64;
  static constexpr int kMaxDiscSides = 1024;
  Eigen::Vector2d arena_min_m = RobotariumArenaMin();  ///< the Robotarium arena
  Eigen::Vector2d arena_max_m = RobotariumArenaMax();
  double wall_margin_m = 0.06;      ///< the cell keeps this far inside the arena walls; >= 0
  double robot_buffer_m = 0.1;      ///< each bisector moves this far towards the robot; >= 0
  double obstacle_buffer_m = 0.12;  ///< each obstacle's line moves this far towards the robot; >= 0

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;

  /// The config keys of the cell (in `controller:` of kind voronoi_coverage).
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("disc_radius_m", disc_radius_m, FieldRule::Positive(),
                  "the cell lies in this disc around the robot (Algorithm 1's circle), m");
    fields.Whole("disc_sides", disc_sides, FieldRule::Within(8, kMaxDiscSides),
                 "the disc as an inscribed polygon with this many sides");
    fields.Number("wall_margin_m", wall_margin_m, FieldRule::NonNegative(),
                  "the cell keeps this far inside the arena walls, m");
    fields.Number("robot_buffer_m", robot_buffer_m, FieldRule::NonNegative(),
                  "each bisector moves this far towards the robot: robots keep 2x apart, m");
    fields.Number("obstacle_buffer_m", obstacle_buffer_m, FieldRule::NonNegative(),
                  "each obstacle's virtual-agent line moves this far towards the robot, m");
  }
};

/// A neighbour as a robot knows it: where it was, and how much further its
/// bisector must move because the neighbour may have moved since (stale
/// radio news).
struct VoronoiNeighbour {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  double extra_buffer_m = 0.0;
};

/// One robot's Voronoi cell and where in it to go.
///
/// The cell (thesis Algorithm 1, buffered): the disc of radius R around the
/// robot, inside the arena, minus the points closer to a neighbour, minus
/// the points closer to an obstacle's virtual agent (the robot mirrored
/// across the obstacle's closest point, thesis Fig. 3.9), every cut moved
/// inwards by a buffer (buffered Voronoi cells, Zhou et al. 2017) so that
/// cells of different robots, and the obstacles, keep apart. A robot that
/// stays inside the cut lines (constraints()) is clear of its neighbours,
/// the obstacles and the walls.
///
/// The coverage centroid: the centroid of the robot's share of the free
/// arena within the disc (disc & arena & unbuffered bisectors, minus the
/// obstacle rectangles) -- the point that lowers the coverage cost (the
/// gradient of the range-limited cost, Cortes et al. 2005). The virtual
/// agent's half-plane gives away the free space behind an obstacle, so the
/// thesis cell's own centroid is not always a descent direction; the goal
/// is the point of the cell closest to the coverage centroid, which is both
/// reachable inside the cell and never farther from the coverage centroid
/// than the robot is (projection onto a convex set containing the robot).
class VoronoiCell {
 public:
  /// @param obstacle_points_m closest points of obstacles (the virtual agents).
  /// @param obstacle_rectangles the obstacles' shapes, taken out of the coverage region.
  /// @throws std::invalid_argument when params are invalid.
  VoronoiCell(const VoronoiCellParams& params, const Eigen::Vector2d& self_m,
              const std::vector<VoronoiNeighbour>& neighbours, const std::vector<Eigen::Vector2d>& obstacle_points_m,
              const std::vector<ObstacleRectangle>& obstacle_rectangles = {});

  /// The buffered cell (may be empty when the robot is squeezed).
  const ConvexPolygon& polygon() const { return polygon_; }
  /// Walls, neighbours and obstacles (not the disc, which limits what the
  /// robot claims, not where it may go).
  const std::vector<HalfPlane>& constraints() const { return constraints_; }
  bool empty() const { return polygon_.empty(); }

  /// Area of the robot's share of the free arena within the disc, m^2.
  double coverage_area_m2() const { return coverage_area_m2_; }
  /// Its centroid; the robot's position when the share has no area.
  const Eigen::Vector2d& coverage_centroid_m() const { return coverage_centroid_m_; }
  /// The point of the cell closest to the coverage centroid; the robot's
  /// position when the cell is empty.
  const Eigen::Vector2d& goal_m() const { return goal_m_; }

 private:
  ConvexPolygon polygon_;
  std::vector<HalfPlane> constraints_;
  double coverage_area_m2_ = 0.0;
  Eigen::Vector2d coverage_centroid_m_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d goal_m_ = Eigen::Vector2d::Zero();
};

}  // namespace dream::agents
