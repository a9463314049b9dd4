#pragma once

#include <cstddef>
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
  /// into `readings`, whose strings and capacity are reused.
  virtual void Read(std::vector<MetricReading>* readings) const = 0;
};

}  // namespace dream::view
