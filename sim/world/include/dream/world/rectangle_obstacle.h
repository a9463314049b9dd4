#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dream/world/obstacle_state.h"
#include "dream/world/rectangle_obstacle_spec.h"

namespace dream::world {

// A virtual rectangle that moves along its (closed) path at constant speed,
// covering speed * dt of arc length per Advance, carrying over across corners.
class RectangleObstacle {
 public:
  // Throws std::invalid_argument if the spec is invalid.
  explicit RectangleObstacle(const RectangleObstacleSpec& spec);

  // One obstacle per spec, checked (valid specs, unique ids); errors start
  // with `owner` and name `<field>[i]`. Throws std::invalid_argument.
  static std::vector<RectangleObstacle> BuildAll(const std::vector<RectangleObstacleSpec>& specs,
                                                 const std::string& owner, const std::string& field);

  // Moves speed * time_step_s along the path (no-op for static obstacles).
  void Advance(double time_step_s);

  int id() const { return spec_.id; }
  const Eigen::Vector2d& center_m() const { return center_m_; }
  double width_m() const { return spec_.width_m; }
  double height_m() const { return spec_.height_m; }
  bool is_static() const { return legs_.empty(); }
  // Velocity of the leg it is travelling now (the one the next Advance moves
  // along); zero for static obstacles.
  Eigen::Vector2d velocity_mps() const;
  const RectangleObstacleSpec& spec() const { return spec_; }

  // Where it is now and how it moves, as a world publishes it.
  ObstacleState State() const;

  // True if the disc touches or overlaps the rectangle (distance from the
  // disc's centre to the closest point of the rectangle <= radius), by
  // ObstacleState's arithmetic.
  bool IntersectsDisc(double center_x_m, double center_y_m, double radius_m) const;

 private:
  struct Leg {
    Eigen::Vector2d start_m;
    Eigen::Vector2d end_m;
    Eigen::Vector2d direction;  // unit vector start -> end
    double length_m;
  };

  RectangleObstacleSpec spec_;
  std::vector<Leg> legs_;  // the closed cycle; empty when static
  double cycle_length_m_ = 0.0;
  std::size_t leg_index_ = 0;
  double distance_along_leg_m_ = 0.0;
  Eigen::Vector2d center_m_;
};

}  // namespace dream::world
