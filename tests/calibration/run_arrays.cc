#include "run_arrays.h"

#include <cstdint>

namespace dream::calibration::test_support {

void ArraysOf(const CalibrationRun& run, formats::NpyArray* poses, formats::NpyArray* commands) {
  const auto n = static_cast<int64_t>(run.track.num_robots);
  const auto t = static_cast<int64_t>(run.track.utime.size());
  poses->shape = {3, n, t};
  commands->shape = {2, n, t};
  poses->values.assign(static_cast<size_t>(3 * n * t), 0.0);
  commands->values.assign(static_cast<size_t>(2 * n * t), 0.0);
  for (int64_t k = 0; k < t; ++k) {
    for (int64_t i = 0; i < n; ++i) {
      const world::Pose2& p = run.track.pose(k, static_cast<int>(i));
      const world::UnicycleCommand& c = run.track.command(k, static_cast<int>(i));
      poses->values[static_cast<size_t>((0 * n + i) * t + k)] = p.x_m;
      poses->values[static_cast<size_t>((1 * n + i) * t + k)] = p.y_m;
      poses->values[static_cast<size_t>((2 * n + i) * t + k)] = p.theta_rad;
      commands->values[static_cast<size_t>((0 * n + i) * t + k)] = c.v_mps;
      commands->values[static_cast<size_t>((1 * n + i) * t + k)] = c.w_radps;
    }
  }
}

}  // namespace dream::calibration::test_support
