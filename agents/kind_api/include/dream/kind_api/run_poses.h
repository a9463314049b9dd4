#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dream::kind_api {

/// A finished run's poses, every step in order, as plain values: what a kind's
/// own metrics (ControllerKind::own_metrics) are computed from, so a kind reads
/// no log and no bus (the tools fill it from the run's log).
struct RunPoses {
  /// One step of the run as the world published it.
  struct Step {
    int64_t step = 0;
    std::vector<Eigen::Vector3d> poses;  ///< per robot: x m, y m, theta rad (world frame)
  };
  std::vector<Step> steps;
};

}  // namespace dream::kind_api
