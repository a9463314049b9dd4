#include "dream/agents/framework/safety_metrics.h"

#include <cmath>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::agents {

SafetyMetrics::SafetyMetrics(double near_miss_m) : near_miss_m_(near_miss_m) {}

void SafetyMetrics::Observe(const WorldSnapshot& world) {
  ++steps_;
  bool near_miss = false;
  // O(N^2) is fine: a run has at most 128 robots (sim_only; 50 otherwise), and this runs after the run.
  for (size_t i = 0; i < world.poses.size(); ++i) {
    for (size_t j = i + 1; j < world.poses.size(); ++j) {
      const double d = (world.poses[i].head<2>() - world.poses[j].head<2>()).norm();
      if (d < min_distance_m_) {
        min_distance_m_ = d;
        min_distance_step_ = world.step;
      }
      near_miss = near_miss || d < near_miss_m_;
    }
  }
  if (near_miss) ++near_miss_steps_;
}

void SafetyMetrics::Write(MetricsReport* report) const {
  if (std::isfinite(min_distance_m_)) {
    report->values["min_pairwise_distance_m"] = min_distance_m_;
    report->values["min_pairwise_distance_step"] = static_cast<double>(min_distance_step_);
    // The Robotarium's collision rule is on the centres' distance (plus its offsets): below this, too close.
    report->thresholds["min_pairwise_distance_m"] = {robotarium::RobotariumConstants::kCollisionDiameterMeters,
                                                     "collision distance 0.135 m"};
  }
  report->values["near_miss_steps"] = static_cast<double>(near_miss_steps_);
  report->values["near_miss_threshold_m"] = near_miss_m_;
}

}  // namespace dream::agents
