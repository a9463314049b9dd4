#include "dream/bridge/obstacle_schedule.h"

#include <climits>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "dream/bridge/submission_format.h"
#include "dream/world/rectangle_obstacle.h"

namespace dream::bridge {

int64_t ObstacleScheduleBytes(int64_t obstacles, int64_t steps) {
  // Saturates instead of overflowing: steps may be anything a config says.
  const int64_t row_bytes = obstacles * kObstacleColumns * int64_t{sizeof(double)};
  if (row_bytes == 0) return 0;
  if (steps >= INT64_MAX / row_bytes) return INT64_MAX;
  return (steps + 1) * row_bytes;
}

formats::NpyArray ObstacleSchedule(const std::vector<world::RectangleObstacleSpec>& specs, double time_step_s,
                                   int64_t steps) {
  if (steps < 0) throw std::invalid_argument("an obstacle schedule needs steps >= 0, got " + std::to_string(steps));
  const int64_t bytes = ObstacleScheduleBytes(static_cast<int64_t>(specs.size()), steps);
  if (bytes > kMaxObstacleScheduleBytes) {
    throw std::invalid_argument("an obstacle schedule of " + std::to_string(specs.size()) + " obstacles over " +
                                std::to_string(steps) + " steps would exceed " +
                                std::to_string(kMaxObstacleScheduleBytes >> 20) + " MiB");
  }
  std::vector<world::RectangleObstacle> obstacles = world::RectangleObstacle::BuildAll(specs, "config", "obstacles");
  const auto m = static_cast<int64_t>(obstacles.size());
  formats::NpyArray array;
  array.shape = {steps + 1, m, kObstacleColumns};
  array.values.resize(static_cast<size_t>((steps + 1) * m * kObstacleColumns));
  double* row = array.values.data();
  for (int64_t k = 0; k <= steps; ++k) {
    for (world::RectangleObstacle& obstacle : obstacles) {
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
