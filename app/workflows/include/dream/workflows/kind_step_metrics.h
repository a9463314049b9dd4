#pragma once

#include <memory>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/agents/framework/experiment_metrics.h"
#include "dream/agents/framework/world_snapshot.h"
#include "dream/view/step_metrics.h"

namespace dream::workflows {

/// A run's metrics step by step for the view's plots, computed by the run's
/// kind with its own code (ControllerFactory::MakeMetrics: the kind's
/// ExperimentMetrics and SafetyMetrics), fed as MetricsFromLog feeds them
/// for summary.json (TakePoses, TakeObstacles), so after the run's last
/// step the readings are summary.json's metrics. A reading is each figure
/// (MetricsReport::values) and the last point of each series, with the
/// threshold the kind declares for it (MetricsReport::thresholds); lists of
/// steps (events) are not plotted.
class KindStepMetrics final : public view::StepMetrics {
 public:
  /// `factory` must outlive this.
  explicit KindStepMetrics(const agent_host::ControllerFactory& factory);
  void Observe(const robot_poses_t& poses, const obstacles_t& obstacles) override;
  void Read(std::vector<view::MetricReading>* readings) const override;

 private:
  std::vector<std::unique_ptr<agents::ExperimentMetrics>> metrics_;
  agents::WorldSnapshot world_;
};

}  // namespace dream::workflows
