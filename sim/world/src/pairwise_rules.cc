#include "pairwise_rules.h"

#include <algorithm>

#include "collision_grid.h"

namespace dream::world {

PairwiseRules::PairwiseRules(const WorldParams& params, std::size_t num_robots)
    : offset_m_(params.collision_offset_m),
      radius_m_(params.collision_diameter_m / 2.0),
      center_x_m_(num_robots),
      center_y_m_(num_robots),
      grid_(std::make_unique<CollisionGrid>(num_robots, params.collision_diameter_m, params.arena)) {}

PairwiseRules::~PairwiseRules() = default;
PairwiseRules::PairwiseRules(PairwiseRules&&) noexcept = default;
PairwiseRules& PairwiseRules::operator=(PairwiseRules&&) noexcept = default;

void PairwiseRules::FindCollidingPairs(std::vector<StepEvents::RobotPair>* pairs) {
  const std::size_t first_new = pairs->size();
  grid_->FindPairs(center_x_m_.data(), center_y_m_.data(), pairs);
  std::sort(pairs->begin() + static_cast<std::ptrdiff_t>(first_new), pairs->end(),
            [](const StepEvents::RobotPair& a, const StepEvents::RobotPair& b) {
              return a.first_robot_id != b.first_robot_id ? a.first_robot_id < b.first_robot_id
                                                          : a.second_robot_id < b.second_robot_id;
            });
}

}  // namespace dream::world
