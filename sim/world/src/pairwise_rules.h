#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/rectangle_obstacle.h"
#include "dream/world/step_events.h"
#include "dream/world/world_params.h"

namespace dream::world {

class CollisionGrid;

// The Robotarium's rules that look at robots together, on the collision
// centres of one step: colliding pairs and robot-obstacle contacts.
// UnicycleWorld (rules on its own poses, in the same pass as the physics) and
// ViolationChecker (rules on poses from elsewhere) both apply them through
// this class, so the two find and order the same events by construction.
// Buffers are sized in the constructor: Apply() never allocates.
class PairwiseRules {
 public:
  PairwiseRules(const WorldParams& params, std::size_t num_robots);
  ~PairwiseRules();
  PairwiseRules(PairwiseRules&&) noexcept;
  PairwiseRules& operator=(PairwiseRules&&) noexcept;

  // Robot i's collision centre: collision_offset_m ahead of its pose (the
  // caller has the heading's cosine and sine already).
  void SetCenter(std::size_t i, const Pose2& pose, double cos_theta, double sin_theta) {
    center_x_m_[i] = pose.x_m + offset_m_ * cos_theta;
    center_y_m_[i] = pose.y_m + offset_m_ * sin_theta;
  }

  // Appends to *events the colliding pairs of the centres set for this step,
  // sorted by (first, second), then every robot-obstacle overlap, by robot id
  // then obstacle order. `Obstacle` is RectangleObstacle or ObstacleState.
  template <typename Obstacle>
  void Apply(const std::vector<Obstacle>& obstacles, StepEvents* events) {
    FindCollidingPairs(&events->colliding_pairs);
    if (obstacles.empty()) return;
    for (std::size_t i = 0; i < center_x_m_.size(); ++i) {
      for (const Obstacle& obstacle : obstacles) {
        if (obstacle.IntersectsDisc(center_x_m_[i], center_y_m_[i], radius_m_)) {
          events->obstacle_contacts.push_back({static_cast<int>(i), IdOf(obstacle)});
        }
      }
    }
  }

 private:
  void FindCollidingPairs(std::vector<StepEvents::RobotPair>* pairs);
  static int IdOf(const RectangleObstacle& obstacle) { return obstacle.id(); }
  static int IdOf(const ObstacleState& obstacle) { return obstacle.id; }

  double offset_m_;
  double radius_m_;
  std::vector<double> center_x_m_;
  std::vector<double> center_y_m_;
  std::unique_ptr<CollisionGrid> grid_;
};

}  // namespace dream::world
