#include "dream/workflows/kind_step_metrics.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <string>

#include "dream/agent_host/snapshot_from_messages.h"
#include "dream/agents/framework/metrics_report.h"
#include "dream/kind_api/controller_kind.h"

namespace dream::workflows {
namespace {

/// Readings' next entry: `name` and `value`, the report's threshold for it.
void Put(const agents::MetricsReport& report, const std::string& name, double value, int64_t step,
         std::vector<view::MetricReading>* readings, size_t* used) {
  if (*used == view::StepMetrics::kMaxReadings) return;
  if (*used == readings->size()) readings->emplace_back();
  view::MetricReading& reading = (*readings)[(*used)++];
  if (reading.name != name) reading.name = name;
  reading.value = value;
  reading.step = step;
  const auto threshold = report.thresholds.find(name);
  if (threshold == report.thresholds.end()) {
    reading.threshold.reset();
    reading.threshold_label.clear();
  } else {
    reading.threshold = threshold->second.value;
    if (reading.threshold_label != threshold->second.label) reading.threshold_label = threshold->second.label;
  }
}

}  // namespace

KindStepMetrics::KindStepMetrics(const agent_host::ControllerFactory& factory, const config::ControllerConfig* config,
                                 const std::string& runtime_dir)
    : metrics_(factory.MakeMetrics()) {
  const kind_api::ControllerKind& kind = factory.registered_kind();
  if (config != nullptr && !runtime_dir.empty() && kind.own_step_metrics) {
    own_ = kind.own_step_metrics(*config, runtime_dir);
  }
}

void KindStepMetrics::Observe(const robot_poses_t& poses, const obstacles_t& obstacles) {
  agent_host::TakeObstacles(obstacles, &world_);
  agent_host::TakePoses(poses, &world_);
  for (auto& m : metrics_) m->Observe(world_);
  step_ = poses.step;
  if (!own_) return;
  // As the bridge hands a finished run's poses to the kind (RunPosesOf): x, y, theta of each robot.
  own_step_.step = poses.step;
  const size_t robots = std::min(
      {static_cast<size_t>(std::max(poses.num_robots, 0)), poses.x.size(), poses.y.size(), poses.theta.size()});
  own_step_.poses.resize(robots);
  for (size_t i = 0; i < robots; ++i) own_step_.poses[i] = {poses.x[i], poses.y[i], poses.theta[i]};
  try {
    own_->Observe(own_step_);
  } catch (const std::exception& e) {
    spdlog::warn("dream view: the controller's own metrics stop at step {}: {}", poses.step, e.what());
    own_.reset();
  }
}

void KindStepMetrics::Read(std::vector<view::MetricReading>* readings) {
  agents::MetricsReport report;
  for (const auto& m : metrics_) m->Write(&report);
  size_t used = 0;
  for (const auto& [name, value] : report.values) Put(report, name, value, step_, readings, &used);
  for (const auto& [name, series] : report.series) {
    if (!series.empty()) Put(report, name, series.back().second, step_, readings, &used);
  }
  if (own_) {
    const size_t kinds = used;
    int64_t own_step = -1;
    try {
      own_step = own_->Read(&own_figures_);
    } catch (const std::exception& e) {
      // The kind's own computing stopped for good (its helper died): its figures stop, the kind's others go on.
      spdlog::warn("dream view: the controller's own metrics stop: {}", e.what());
      own_.reset();
      readings->resize(used);
      return;
    }
    for (const auto& [name, value] : own_figures_) {
      const auto end = readings->begin() + static_cast<std::ptrdiff_t>(kinds);
      const bool named =
          std::any_of(readings->begin(), end, [&](const view::MetricReading& r) { return r.name == name; });
      if (!named) Put(report, name, value, own_step, readings, &used);  // as summary.json adds them
    }
    if (own_->last_error() != own_error_) {
      own_error_ = own_->last_error();
      spdlog::warn("dream view: the controller's metrics(), at some step: {}", own_error_);
    }
  }
  readings->resize(used);
}

bool KindStepMetrics::Pending() const { return own_ && own_->Pending(); }

}  // namespace dream::workflows
