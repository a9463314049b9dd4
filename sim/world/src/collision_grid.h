#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dream/world/arena.h"
#include "dream/world/step_events.h"

namespace dream::world {

// Finds all pairs of points at most a given distance apart in O(N) time.
// Points are counting-sorted into a dense row-major grid over the arena (plus
// a margin) whose cells are at least that distance wide, so partners sit in
// the same or an adjacent cell. Each pair is examined from one side only:
// later points of the same cell and the cell to the right (one contiguous
// slot range), and the three cells of the next row (another contiguous
// range). Points outside the covered area are clamped into its edge cells,
// which keeps every close pair in adjacent cells (clamping never moves two
// cells further apart), so results stay exact for any finite position.
// Buffers are sized in the constructor; FindPairs only appends to `pairs`.
class CollisionGrid {
 public:
  CollisionGrid(std::size_t num_points, double max_distance_m, const Arena& arena);

  // Appends every pair (i < j) with sqrt(dx*dx + dy*dy) <= max_distance_m to
  // *pairs, in no particular order. x_m and y_m hold num_points finite values.
  void FindPairs(const double* x_m, const double* y_m, std::vector<StepEvents::RobotPair>* pairs);

  double cell_size_m() const { return cell_size_m_; }

 private:
  std::size_t num_points_;
  double max_distance_m_;
  double cell_size_m_;
  double origin_x_m_;
  double origin_y_m_;
  double inverse_cell_size_per_m_;
  // Interior cells are 1..columns_ and 1..rows_; a ring of always-empty
  // padding cells lets neighbour ranges run without edge checks.
  double max_column_;
  double max_row_;
  std::size_t stride_;

  std::vector<std::uint32_t> cell_of_point_;
  // cell_start_[c] .. cell_start_[c + 1] are the slots of cell c.
  std::vector<std::uint32_t> cell_start_;
  // Points in cell order (structure of arrays for the scans).
  std::vector<std::uint32_t> sorted_cell_;
  std::vector<std::int32_t> sorted_id_;
  std::vector<double> sorted_x_m_;
  std::vector<double> sorted_y_m_;
};

}  // namespace dream::world
