#include "dream/view/metric_timeline.h"

#include <algorithm>

namespace dream::view {

bool MetricTimeline::Due() { return offered_++ % stride_ == 0; }

MetricTimeline::Series* MetricTimeline::Find(const std::string& name) {
  for (Series& s : series_) {
    if (s.name == name) return &s;
  }
  if (series_.size() >= kMaxSeries) return nullptr;
  Series& added = series_.emplace_back();
  added.name = name;
  added.points.reserve(kMaxPoints);
  return &added;
}

void MetricTimeline::Halve() {
  // Every other point kept, from the first: the steps the doubled stride would have recorded.
  for (Series& s : series_) {
    const size_t n = s.points.size();
    size_t kept = 0;
    for (size_t i = 0; i < n; i += 2) s.points[kept++] = s.points[i];
    s.points.resize(kept);
  }
  stride_ *= 2;
}

void MetricTimeline::Record(int64_t step, const std::vector<MetricReading>& readings) {
  bool full = false;
  for (const MetricReading& reading : readings) {
    Series* s = Find(reading.name);
    if (s == nullptr) continue;
    s->threshold = reading.threshold;
    if (s->threshold_label != reading.threshold_label) s->threshold_label = reading.threshold_label;
    const double at = static_cast<double>(reading.step >= 0 ? reading.step : step);
    if (!s->points.empty() && s->points.back()[0] >= at) continue;
    s->points.push_back({at, reading.value});
    full = full || s->points.size() >= kMaxPoints;
  }
  if (full) Halve();
}

void MetricTimeline::AddSeries(const std::string& name, const std::vector<std::array<double, 2>>& points) {
  if (points.empty() || series_.size() >= kMaxSeries) return;
  for (const Series& s : series_) {
    if (s.name == name) return;
  }
  Series& added = series_.emplace_back();
  added.name = name;
  const size_t every = (points.size() + kMaxPoints - 1) / kMaxPoints;  // at least 1
  added.points.reserve(std::min(points.size(), kMaxPoints));
  // The last point always kept: the figure after the run.
  for (size_t i = (points.size() - 1) % every; i < points.size(); i += every) added.points.push_back(points[i]);
}

MetricTimeline MetricTimeline::OfRun(const run_log::RunLog& log, StepMetrics& metrics) {
  MetricTimeline timeline;
  std::vector<MetricReading> readings;
  const size_t steps = log.poses().size();
  for (size_t i = 0; i < steps; ++i) {
    metrics.Observe(log.poses()[i], log.obstacles_at(i));
    if (timeline.Due() || i + 1 == steps) {
      metrics.Read(&readings);
      timeline.Record(log.poses()[i].step, readings);
    }
  }
  return timeline;
}

}  // namespace dream::view
