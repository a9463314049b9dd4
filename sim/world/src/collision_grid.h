#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dream/sim/step_events.h"

namespace dream::sim {

// Finds all pairs of points at most a given distance apart in O(N) expected
// time: points are counting-sorted into a hashed uniform grid whose cells are
// at least that distance wide, so partners sit in the same or an adjacent
// cell. Each pair is examined from exactly one side (own cell + four
// "forward" neighbours), and exact cell coordinates are compared so hash
// collisions never double-count. Buffers are sized in the constructor.
class CollisionGrid {
 public:
  CollisionGrid(std::size_t num_points, double max_distance_m);

  // Appends every pair (i < j) with sqrt(dx*dx + dy*dy) <= max_distance_m to
  // *pairs, in no particular order. x_m and y_m hold num_points finite values.
  void FindPairs(const double* x_m, const double* y_m,
                 std::vector<StepEvents::RobotPair>* pairs);

 private:
  std::uint32_t BucketOf(std::int32_t cell_x, std::int32_t cell_y) const;
  std::int32_t CellIndex(double coordinate_m) const;

  std::size_t num_points_;
  double max_distance_m_;
  double inverse_cell_size_per_m_;
  std::uint32_t bucket_mask_;

  std::vector<std::uint32_t> bucket_of_point_;
  // bucket_start_[b] .. bucket_start_[b + 1] are bucket b's slots.
  std::vector<std::uint32_t> bucket_start_;
  // Points in bucket order (structure of arrays for the scan).
  std::vector<std::int32_t> sorted_id_;
  std::vector<std::int32_t> sorted_cell_x_;
  std::vector<std::int32_t> sorted_cell_y_;
  std::vector<double> sorted_x_m_;
  std::vector<double> sorted_y_m_;
  std::vector<std::int32_t> cell_x_;
  std::vector<std::int32_t> cell_y_;
};

}  // namespace dream::sim
