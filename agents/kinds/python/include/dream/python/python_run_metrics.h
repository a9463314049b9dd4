#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dream/kind_api/run_poses.h"

namespace dream::python {

/// A Python controller's own metrics and goal (its class's metrics(), goal()
/// and goal_points(), docs/python-controllers.md#your-own-goal-and-metrics),
/// computed from a finished run's poses by a short-lived `python3 -I
/// python/dream/run_metrics.py` (the Python the agents embed, found at build
/// time), so the tools never map libpython and a Robotarium submission never
/// needs this code. What the python kind's hooks (ControllerKind::own_metrics,
/// goals_before_run) run.
class PythonRunMetrics {
 public:
  /// The most seconds the class's functions may take together.
  static constexpr double kTimeoutS = 120.0;

  /// {"declared": [...], "metrics": {...}, "goal": {...} or null,
  /// "goal_points": [[[x, y], ...] per robot]} for the controller of
  /// `spec_json` (the kind's ControllerKind::runtime_spec) over the run's poses.
  /// @throws std::runtime_error naming the module and what failed (its
  ///         exception with file and line, a bad return value, a timeout),
  ///         or the step whose robots differ from the first step's.
  static nlohmann::json Compute(const std::string& runtime_dir, const std::string& spec_json,
                                const kind_api::RunPoses& poses);

  /// The most seconds goal_points() may take, before a run (the view draws them).
  static constexpr double kGoalPointsTimeoutS = 30.0;

  /// Only the goal points the class declares, from its config before any
  /// run (`run_metrics.py --goal-points`): [x, y] points per robot, none
  /// when it declares none. The view draws them.
  /// @throws std::runtime_error as Compute() does, and naming the script when
  ///         what it wrote is not one list of [x, y] pairs per robot.
  static std::vector<std::vector<Eigen::Vector2d>> GoalPoints(const std::string& runtime_dir,
                                                              const std::string& spec_json, int num_robots);
};

}  // namespace dream::python
