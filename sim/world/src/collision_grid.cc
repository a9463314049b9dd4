#include "collision_grid.h"

#include <algorithm>
#include <cmath>

namespace dream::sim {
namespace {

// Cell coordinates are clamped here so far-away points cannot overflow int32.
// Clamping keeps neighbours neighbours (it never increases index distance).
constexpr double kMaxCellIndex = 1 << 30;

// Cells a hair wider than the distance, so rounding in x / cell can never
// put two points within the distance two cells apart.
constexpr double kCellWidening = 1.0 + 1e-9;

std::uint32_t BucketCountFor(std::size_t num_points) {
  std::uint32_t buckets = 16;
  while (buckets < 2 * num_points) buckets *= 2;
  return buckets;
}

}  // namespace

CollisionGrid::CollisionGrid(std::size_t num_points, double max_distance_m)
    : num_points_(num_points),
      max_distance_m_(max_distance_m),
      inverse_cell_size_per_m_(1.0 / (max_distance_m * kCellWidening)),
      bucket_mask_(BucketCountFor(num_points) - 1),
      bucket_of_point_(num_points),
      bucket_start_(static_cast<std::size_t>(bucket_mask_) + 2),
      sorted_id_(num_points),
      sorted_cell_x_(num_points),
      sorted_cell_y_(num_points),
      sorted_x_m_(num_points),
      sorted_y_m_(num_points),
      cell_x_(num_points),
      cell_y_(num_points) {}

std::int32_t CollisionGrid::CellIndex(double coordinate_m) const {
  const double cell = std::floor(coordinate_m * inverse_cell_size_per_m_);
  return static_cast<std::int32_t>(std::clamp(cell, -kMaxCellIndex, kMaxCellIndex));
}

std::uint32_t CollisionGrid::BucketOf(std::int32_t cell_x, std::int32_t cell_y) const {
  std::uint32_t hash = static_cast<std::uint32_t>(cell_x) * 0x9E3779B1u ^
                       static_cast<std::uint32_t>(cell_y) * 0x85EBCA77u;
  hash ^= hash >> 16;
  return hash & bucket_mask_;
}

void CollisionGrid::FindPairs(const double* x_m, const double* y_m,
                              std::vector<StepEvents::RobotPair>* pairs) {
  const std::size_t n = num_points_;
  if (n < 2) return;

  // Counting sort by bucket: counts, inclusive prefix sums, then a reverse
  // scatter that leaves bucket_start_[b] at the bucket's first slot.
  std::fill(bucket_start_.begin(), bucket_start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) {
    cell_x_[i] = CellIndex(x_m[i]);
    cell_y_[i] = CellIndex(y_m[i]);
    const std::uint32_t bucket = BucketOf(cell_x_[i], cell_y_[i]);
    bucket_of_point_[i] = bucket;
    ++bucket_start_[bucket];
  }
  const std::size_t num_buckets = static_cast<std::size_t>(bucket_mask_) + 1;
  for (std::size_t b = 1; b < num_buckets; ++b) bucket_start_[b] += bucket_start_[b - 1];
  bucket_start_[num_buckets] = static_cast<std::uint32_t>(n);
  for (std::size_t i = n; i-- > 0;) {
    const std::uint32_t slot = --bucket_start_[bucket_of_point_[i]];
    sorted_id_[slot] = static_cast<std::int32_t>(i);
    sorted_cell_x_[slot] = cell_x_[i];
    sorted_cell_y_[slot] = cell_y_[i];
    sorted_x_m_[slot] = x_m[i];
    sorted_y_m_[slot] = y_m[i];
  }

  const double max_distance_m = max_distance_m_;
  auto test_pair = [&](std::uint32_t a, std::uint32_t b) {
    // Same expression as numpy's norm of the 2-vector difference.
    const double dx = sorted_x_m_[a] - sorted_x_m_[b];
    const double dy = sorted_y_m_[a] - sorted_y_m_[b];
    if (std::sqrt(dx * dx + dy * dy) <= max_distance_m) {
      const int id_a = sorted_id_[a];
      const int id_b = sorted_id_[b];
      pairs->push_back(id_a < id_b ? StepEvents::RobotPair{id_a, id_b}
                                   : StepEvents::RobotPair{id_b, id_a});
    }
  };

  // Forward half of the 8-neighbourhood; the other half is covered when the
  // neighbour is the point being scanned.
  static constexpr std::int32_t kForwardCells[4][2] = {{1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  for (std::uint32_t p = 0; p < n; ++p) {
    const std::int32_t cx = sorted_cell_x_[p];
    const std::int32_t cy = sorted_cell_y_[p];
    // Own cell: later slots of the same bucket only.
    const std::uint32_t own_end = bucket_start_[bucket_of_point_[static_cast<std::size_t>(sorted_id_[p])] + 1];
    for (std::uint32_t q = p + 1; q < own_end; ++q) {
      if (sorted_cell_x_[q] == cx && sorted_cell_y_[q] == cy) test_pair(p, q);
    }
    for (const auto& offset : kForwardCells) {
      const std::int32_t nx = cx + offset[0];
      const std::int32_t ny = cy + offset[1];
      const std::uint32_t bucket = BucketOf(nx, ny);
      const std::uint32_t end = bucket_start_[bucket + 1];
      for (std::uint32_t q = bucket_start_[bucket]; q < end; ++q) {
        if (sorted_cell_x_[q] == nx && sorted_cell_y_[q] == ny) test_pair(p, q);
      }
    }
  }
}

}  // namespace dream::sim
