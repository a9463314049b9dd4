#pragma once

#include <Eigen/Core>
#include <vector>

#include "dream/agents/framework/world_snapshot.h"

namespace dream::voronoi_coverage {

/// The coverage cost of robot positions p_i over the free arena Q (the arena
/// minus the obstacles): H = integral over Q of min_i ||q - p_i||^2 dq, in
/// m^4 (Cortes et al., Coverage Control for Mobile Sensing Networks). Lower
/// is better covered.
///
/// Computed exactly, not on a grid: each robot's full Voronoi cell in the
/// arena is a convex polygon (the arena clipped by every bisector); its
/// second moment about the robot, minus that of its part inside the
/// obstacles, is its share. Overlapping obstacles are handled by
/// inclusion-exclusion over their (rectangular) intersections. Only
/// rounding limits the precision (about 1e-15 relative).
class CoverageCost {
 public:
  CoverageCost(const Eigen::Vector2d& arena_min_m, const Eigen::Vector2d& arena_max_m);

  /// Robots at the same position count once (they cover the same points).
  double Evaluate(const std::vector<Eigen::Vector2d>& positions_m,
                  const std::vector<agents::ObstacleView>& obstacles) const;

 private:
  Eigen::Vector2d arena_min_m_;
  Eigen::Vector2d arena_max_m_;
};

}  // namespace dream::voronoi_coverage
