#include "dream/workflows/kind_step_metrics.h"

#include <string>

#include "dream/agent_host/snapshot_from_messages.h"
#include "dream/agents/framework/metrics_report.h"

namespace dream::workflows {
namespace {

/// Readings' next entry: `name` and `value`, the report's threshold for it.
void Put(const agents::MetricsReport& report, const std::string& name, double value,
         std::vector<view::MetricReading>* readings, size_t* used) {
  if (*used == view::StepMetrics::kMaxReadings) return;
  if (*used == readings->size()) readings->emplace_back();
  view::MetricReading& reading = (*readings)[(*used)++];
  if (reading.name != name) reading.name = name;
  reading.value = value;
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

KindStepMetrics::KindStepMetrics(const agent_host::ControllerFactory& factory) : metrics_(factory.MakeMetrics()) {}

void KindStepMetrics::Observe(const robot_poses_t& poses, const obstacles_t& obstacles) {
  agent_host::TakeObstacles(obstacles, &world_);
  agent_host::TakePoses(poses, &world_);
  for (auto& m : metrics_) m->Observe(world_);
}

void KindStepMetrics::Read(std::vector<view::MetricReading>* readings) const {
  agents::MetricsReport report;
  for (const auto& m : metrics_) m->Write(&report);
  size_t used = 0;
  for (const auto& [name, value] : report.values) Put(report, name, value, readings, &used);
  for (const auto& [name, series] : report.series) {
    if (!series.empty()) Put(report, name, series.back().second, readings, &used);
  }
  readings->resize(used);
}

}  // namespace dream::workflows
