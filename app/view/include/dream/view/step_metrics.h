#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"

namespace dream::view {

/// One figure of a run's metrics after some step, as its plot over time
/// shows it: its value then, and the line it is judged against, if any.
struct MetricReading {
  std::string name;
  double value = 0.0;
  std::optional<double> threshold;  ///< the goal's tolerance, the collision distance, ...
  std::string threshold_label;      ///< what that line is ("goal: within 0.05 m")
  /// The step the value is of: the last observed, or an earlier one for a
  /// figure computed elsewhere and later (a Python controller's metrics()).
  int64_t step = -1;
};

/// A run's metrics followed step by step, for the view's plots: the view
/// knows no kind, so the caller (dream view's workflow, which has the run's
/// config) gives one that computes the kind's own figures with the kind's
/// own code, the same that writes summary.json's metrics after the run.
class StepMetrics {
 public:
  /// Figures read at most, whatever a kind writes.
  static constexpr size_t kMaxReadings = 32;

  virtual ~StepMetrics() = default;
  /// Every step of the run, in order, with the obstacles of that step.
  virtual void Observe(const robot_poses_t& poses, const obstacles_t& obstacles) = 0;
  /// The figures after the steps observed so far (at most kMaxReadings),
  /// into `readings`, whose strings and capacity are reused. Never waits for
  /// a figure computed elsewhere: it gives the newest there is.
  virtual void Read(std::vector<MetricReading>* readings) = 0;
  /// Whether some figure is still being computed for steps observed (elsewhere:
  /// Read collects it later); false for figures computed in Observe.
  virtual bool Pending() const { return false; }
};

}  // namespace dream::view
