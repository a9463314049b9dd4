#pragma once

#include <cstdint>
#include <vector>

#include "dream/world/pose2.h"
#include "dream/world/realism_params.h"
#include "dream/world/unicycle_command.h"

namespace dream::calibration {

/// The maintainers' measure of open-loop drives from rest (issue 32,
/// docs/experiments.md "The lab preset"), the one the real GRITSbot X
/// figures were taken with, so a model is held against them by the same
/// yardstick: the effective delay of a straight drive and the turning of a
/// circle, from one robot's measured poses, step 0 being the step the
/// constant command was first sent, on the run's clock (a lab's steps, and
/// the lab model's, last longer than 33 ms on average).
class OpenLoopDriveMeasure {
 public:
  /// Robots driven side by side from rest, and when each step was taken.
  struct Drive {
    std::vector<double> time_s;                    ///< per step, from the first command
    std::vector<std::vector<world::Pose2>> poses;  ///< per robot, per step: as measured
  };

  /// Poses smoothed by a centred 9-step moving average, the path length s(t)
  /// along them, the steady line s = v (t - t0) fitted over steps 60-200:
  /// t0, in seconds. @throws std::invalid_argument with under 205 poses (or
  /// times not one per pose).
  static double EffectiveDelay(const std::vector<world::Pose2>& poses, const std::vector<double>& time_s);

  /// The steady turning rate after the first 100 steps (a line through the
  /// unwrapped heading), divided by the commanded rate `w_radps`.
  /// @throws std::invalid_argument with under 200 poses or w_radps == 0.
  static double TurningRatio(const std::vector<world::Pose2>& poses, const std::vector<double>& time_s, double w_radps);

  /// Drives `robots` robots of the lab model `realism` (world::RealisticWorld,
  /// seeded) from rest with `command` held for `steps` steps, side by side:
  /// each robot's measured poses from before the first command on, and the
  /// model's clock.
  static Drive Simulate(const world::RealismParams& realism, uint64_t seed, int robots, int steps,
                        world::UnicycleCommand command);
};

}  // namespace dream::calibration
