#pragma once

#include <cstdint>
#include <limits>

#include "dream/agents/framework/experiment_metrics.h"

namespace dream::agents {

/// Figures every experiment reports: the minimum distance between any two
/// robot centres and when it happened, and the steps with a pair closer than
/// a near-miss threshold.
class SafetyMetrics final : public ExperimentMetrics {
 public:
  /// @param near_miss_m a pair of centres closer than this is a near miss
  ///        (default: the Robotarium's collision distance plus 5 cm).
  explicit SafetyMetrics(double near_miss_m = 0.185);
  void Observe(const WorldSnapshot& world) override;
  void Write(MetricsReport* report) const override;

  double min_distance_m() const { return min_distance_m_; }

 private:
  double near_miss_m_;
  double min_distance_m_ = std::numeric_limits<double>::infinity();
  int64_t min_distance_step_ = -1;
  int64_t near_miss_steps_ = 0;
  int64_t steps_ = 0;
};

}  // namespace dream::agents
