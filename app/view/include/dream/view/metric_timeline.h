#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dream/run_log/run_log.h"
#include "dream/view/step_metrics.h"

namespace dream::view {

/// A run's metrics over time, bounded: each figure a series of (step, value)
/// of at most kMaxPoints, however long the run. It records every
/// stride-th step it is offered (Due()); when a series is full every other
/// point is dropped and the stride doubles, so a run of any length keeps
/// between kMaxPoints / 2 and kMaxPoints points a series, evenly spread.
/// The storage is reserved once per series: recording never reallocates.
class MetricTimeline {
 public:
  static constexpr size_t kMaxPoints = 1024;  ///< per series (even)
  static constexpr size_t kMaxSeries = StepMetrics::kMaxReadings;

  struct Series {
    std::string name;
    std::vector<std::array<double, 2>> points;  ///< {step, value}, in step order
    std::optional<double> threshold;
    std::string threshold_label;
  };

  /// Counts one step offered; true when it is to be recorded (every
  /// stride-th, the first included).
  bool Due();
  /// The figures at `step` (each at its own step when it says one: a reading
  /// whose name is new starts a series, up to kMaxSeries; a step not after a
  /// series' last is not added to it).
  void Record(int64_t step, const std::vector<MetricReading>& readings);
  /// A whole series known at once (a Python controller's metrics() over the
  /// run, from summary.json), kept evenly to at most kMaxPoints; ignored
  /// when a series of that name is already here or kMaxSeries are.
  void AddSeries(const std::string& name, const std::vector<std::array<double, 2>>& points);

  const std::vector<Series>& series() const { return series_; }
  /// Steps offered per point recorded now.
  int64_t stride() const { return stride_; }

  /// `metrics` fed every step of `log` (its poses and the obstacles of
  /// each), read on the due steps and on the last, so a series' last point
  /// is the figure after the run: what summary.json's metrics say.
  static MetricTimeline OfRun(const run_log::RunLog& log, StepMetrics& metrics);

 private:
  Series* Find(const std::string& name);
  void Halve();

  std::vector<Series> series_;
  int64_t stride_ = 1;
  int64_t offered_ = 0;
};

}  // namespace dream::view
