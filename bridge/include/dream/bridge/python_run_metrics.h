#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "dream/run_log/run_log.h"

namespace dream::bridge {

/// A Python controller's own metrics and goal (its class's metrics(), goal()
/// and goal_points(), docs/python-controllers.md#your-own-goal-and-metrics),
/// computed from a finished run's poses by a short-lived `python3 -I
/// python/dream/run_metrics.py` (the Python the agents embed, found at build
/// time), so the tools never map libpython and a Robotarium submission never
/// needs this code.
class PythonRunMetrics {
 public:
  /// The most seconds the class's functions may take together.
  static constexpr double kTimeoutS = 120.0;

  /// {"declared": [...], "metrics": {...}, "goal": {...} or null,
  /// "goal_points": [[[x, y], ...] per robot]} for the controller of
  /// `spec_json` (the kind's ControllerKind::runtime_spec) over `log`'s poses.
  /// @throws std::runtime_error naming the module and what failed (its
  ///         exception with file and line, a bad return value, a timeout).
  static nlohmann::json Compute(const std::string& runtime_dir, const std::string& spec_json,
                                const run_log::RunLog& log);

  /// The most seconds goal_points() may take, before a run (the view draws them).
  static constexpr double kGoalPointsTimeoutS = 30.0;

  /// Only the goal points the class declares, from its config before any
  /// run (`run_metrics.py --goal-points`): [[[x, y], ...] per robot], empty
  /// when it declares none. The view draws them.
  /// @throws std::runtime_error as Compute() does.
  static nlohmann::json GoalPoints(const std::string& runtime_dir, const std::string& spec_json, int num_robots);
};

}  // namespace dream::bridge
