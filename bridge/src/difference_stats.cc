#include "dream/bridge/difference_stats.h"

#include <cmath>

namespace dream::bridge {

void DifferenceStats::Add(double difference, int64_t step) {
  const double size = std::abs(difference);
  sum_of_squares_ += size * size;
  // A NaN never becomes the largest (the RMS shows it); of equal sizes the first stays.
  if (size > max_ || (max_step_ < 0 && size == max_)) {
    max_ = size;
    max_step_ = step;
  }
  ++count_;
}

void DifferenceStats::Merge(const DifferenceStats& other) {
  if (other.count_ == 0) return;
  sum_of_squares_ += other.sum_of_squares_;
  if (other.max_ > max_ || (max_step_ < 0 && other.max_step_ >= 0 && other.max_ == max_)) {
    max_ = other.max_;
    max_step_ = other.max_step_;
  }
  count_ += other.count_;
}

double DifferenceStats::Rms() const {
  return count_ == 0 ? 0.0 : std::sqrt(sum_of_squares_ / static_cast<double>(count_));
}

}  // namespace dream::bridge
