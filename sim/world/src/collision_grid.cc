#include "collision_grid.h"

#include <algorithm>
#include <cmath>

namespace dream::world {
namespace {

// Cells a hair wider than the distance, so rounding in (x - origin) / cell
// can never put two points within the distance two cells apart.
constexpr double kCellWidening = 1.0 + 1e-9;
// The grid also covers this much around the arena, so robots that stray out
// still spread over distinct cells.
constexpr double kMarginMeters = 1.0;
// At most this many cells per point (and at least kMinCells): bounds the
// per-step clear and prefix sum when the arena is huge for its robots; the
// cells then grow, which costs distance checks but never correctness.
constexpr double kMaxCellsPerPoint = 8.0;
constexpr double kMinCells = 4096.0;

}  // namespace

CollisionGrid::CollisionGrid(std::size_t num_points, double max_distance_m, const Arena& arena)
    : num_points_(num_points), max_distance_m_(max_distance_m) {
  origin_x_m_ = arena.x_min_m - kMarginMeters;
  origin_y_m_ = arena.y_min_m - kMarginMeters;
  const double width_m = arena.width_m() + 2.0 * kMarginMeters;
  const double height_m = arena.height_m() + 2.0 * kMarginMeters;
  const double max_cells = std::max(kMinCells, kMaxCellsPerPoint * static_cast<double>(num_points));
  cell_size_m_ = std::max(max_distance_m * kCellWidening, std::sqrt(width_m * height_m / max_cells));
  inverse_cell_size_per_m_ = 1.0 / cell_size_m_;
  const auto columns = static_cast<std::size_t>(std::max(1.0, std::ceil(width_m * inverse_cell_size_per_m_)));
  const auto rows = static_cast<std::size_t>(std::max(1.0, std::ceil(height_m * inverse_cell_size_per_m_)));
  max_column_ = static_cast<double>(columns - 1);
  max_row_ = static_cast<double>(rows - 1);
  stride_ = columns + 2;
  cell_start_.resize(stride_ * (rows + 2) + 1);
  cell_of_point_.resize(num_points);
  sorted_cell_.resize(num_points);
  sorted_id_.resize(num_points);
  sorted_x_m_.resize(num_points);
  sorted_y_m_.resize(num_points);
}

void CollisionGrid::FindPairs(const double* x_m, const double* y_m, std::vector<StepEvents::RobotPair>* pairs) {
  const std::size_t n = num_points_;
  if (n < 2) return;

  // Counting sort by cell: counts, inclusive prefix sums, then a reverse
  // scatter that leaves cell_start_[c] at the cell's first slot.
  std::fill(cell_start_.begin(), cell_start_.end(), 0u);
  for (std::size_t i = 0; i < n; ++i) {
    // Clamped to >= 0 first, so truncation is floor.
    const double column = std::clamp((x_m[i] - origin_x_m_) * inverse_cell_size_per_m_, 0.0, max_column_);
    const double row = std::clamp((y_m[i] - origin_y_m_) * inverse_cell_size_per_m_, 0.0, max_row_);
    const auto cell = static_cast<std::uint32_t>((static_cast<std::size_t>(row) + 1) * stride_ +
                                                 static_cast<std::size_t>(column) + 1);
    cell_of_point_[i] = cell;
    ++cell_start_[cell];
  }
  const std::size_t num_cells = cell_start_.size() - 1;
  for (std::size_t c = 1; c < num_cells; ++c) cell_start_[c] += cell_start_[c - 1];
  cell_start_[num_cells] = static_cast<std::uint32_t>(n);
  for (std::size_t i = n; i-- > 0;) {
    const std::uint32_t slot = --cell_start_[cell_of_point_[i]];
    sorted_cell_[slot] = cell_of_point_[i];
    sorted_id_[slot] = static_cast<std::int32_t>(i);
    sorted_x_m_[slot] = x_m[i];
    sorted_y_m_[slot] = y_m[i];
  }

  const double max_distance_m = max_distance_m_;
  auto scan = [&](std::uint32_t p, std::uint32_t begin, std::uint32_t end) {
    const double x = sorted_x_m_[p];
    const double y = sorted_y_m_[p];
    for (std::uint32_t q = begin; q < end; ++q) {
      // Same expression as numpy's norm of the 2-vector difference.
      const double dx = x - sorted_x_m_[q];
      const double dy = y - sorted_y_m_[q];
      if (std::sqrt(dx * dx + dy * dy) <= max_distance_m) {
        const int a = sorted_id_[p];
        const int b = sorted_id_[q];
        pairs->push_back(a < b ? StepEvents::RobotPair{a, b} : StepEvents::RobotPair{b, a});
      }
    }
  };
  const std::size_t stride = stride_;
  for (std::uint32_t p = 0; p < n; ++p) {
    const std::size_t cell = sorted_cell_[p];
    // Rest of this cell, then the cell to its right: adjacent slots.
    scan(p, p + 1, cell_start_[cell + 2]);
    // The three cells below-left, below, below-right of the next row.
    scan(p, cell_start_[cell + stride - 1], cell_start_[cell + stride + 2]);
  }
}

}  // namespace dream::world
