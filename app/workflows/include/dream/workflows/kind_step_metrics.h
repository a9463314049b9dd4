#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dream/agent_host/controller_factory.h"
#include "dream/agents/framework/experiment_metrics.h"
#include "dream/agents/framework/world_snapshot.h"
#include "dream/config/controller_config.h"
#include "dream/kind_api/own_step_metrics.h"
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
///
/// With a runtime folder, the kind's own metrics too (ControllerKind::
/// own_step_metrics: a Python controller's metrics(), computed by a helper
/// process while the run goes on, each reading at the step it is of), the
/// figures no other metric names, as summary.json adds them. Should the
/// kind's own computing fail for good (its helper died), its figures stop,
/// said once, and the kind's others go on.
class KindStepMetrics final : public view::StepMetrics {
 public:
  /// `factory` must outlive this. `config` and `runtime_dir` (the Python
  /// runtime, process::DataFiles) for the kind's own metrics; an empty
  /// `runtime_dir` asks for none.
  /// @throws std::runtime_error when the kind's own metrics cannot start.
  explicit KindStepMetrics(const agent_host::ControllerFactory& factory,
                           const config::ControllerConfig* config = nullptr, const std::string& runtime_dir = "");
  void Observe(const robot_poses_t& poses, const obstacles_t& obstacles) override;
  void Read(std::vector<view::MetricReading>* readings) override;
  bool Pending() const override;

 private:
  std::vector<std::unique_ptr<agents::ExperimentMetrics>> metrics_;
  agents::WorldSnapshot world_;
  int64_t step_ = -1;  // the last observed
  std::unique_ptr<kind_api::OwnStepMetrics> own_;
  kind_api::RunPoses::Step own_step_;  // reused for each step handed to own_
  std::vector<kind_api::OwnStepMetrics::Figure> own_figures_;
  std::string own_error_;  // the last said
};

}  // namespace dream::workflows
