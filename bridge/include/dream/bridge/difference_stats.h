#pragma once

#include <cstdint>

namespace dream::bridge {

/// How large a difference between two runs is over their steps: its root mean
/// square, its largest value and the step of that. A run comparison keeps one
/// per robot for position and heading, a lab replay's CommandAgreement one per
/// robot for v and w, so every such figure is summed and rounded one way.
class DifferenceStats {
 public:
  /// Takes |difference| at `step`. Of equal largest values the first is kept.
  void Add(double difference, int64_t step);
  /// Takes every sample `other` took (a whole run's figure from its robots').
  void Merge(const DifferenceStats& other);

  int64_t count() const { return count_; }
  /// 0 when nothing was taken.
  double Rms() const;
  double max() const { return max_; }
  /// The step of max(); -1 when nothing was taken (or only NaN).
  int64_t max_step() const { return max_step_; }

 private:
  int64_t count_ = 0;
  double sum_of_squares_ = 0.0;
  double max_ = 0.0;
  int64_t max_step_ = -1;
};

}  // namespace dream::bridge
