#include "dream/bridge/obstacle_schedule.h"

#include "dream/bridge/submission_format.h"
#include "dream/world/rectangle_obstacle.h"

namespace dream::bridge {

NpyArray ObstacleSchedule(const std::vector<sim::RectangleObstacleSpec>& specs, double time_step_s, int64_t steps) {
  std::vector<sim::RectangleObstacle> obstacles = sim::RectangleObstacle::BuildAll(specs, "config", "obstacles");
  const auto m = static_cast<int64_t>(obstacles.size());
  NpyArray array;
  array.shape = {steps + 1, m, kObstacleColumns};
  array.values.resize(static_cast<size_t>((steps + 1) * m * kObstacleColumns));
  double* row = array.values.data();
  for (int64_t k = 0; k <= steps; ++k) {
    for (sim::RectangleObstacle& obstacle : obstacles) {
      const Eigen::Vector2d velocity = obstacle.velocity_mps();
      row[kObstacleId] = obstacle.id();
      row[kObstacleCenterX] = obstacle.center_m().x();
      row[kObstacleCenterY] = obstacle.center_m().y();
      row[kObstacleWidth] = obstacle.width_m();
      row[kObstacleHeight] = obstacle.height_m();
      row[kObstacleVelocityX] = velocity.x();
      row[kObstacleVelocityY] = velocity.y();
      row += kObstacleColumns;
      // The world advances its obstacles at the end of each step.
      obstacle.Advance(time_step_s);
    }
  }
  return array;
}

}  // namespace dream::bridge
