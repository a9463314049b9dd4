#include "dream/agent_host/snapshot_from_messages.h"

namespace dream::agent_host {

void TakePoses(const robot_poses_t& poses, agents::WorldSnapshot* world) {
  const size_t n = poses.x.size();
  world->step = poses.step;
  world->poses.resize(n);
  world->velocities.resize(n);
  for (size_t i = 0; i < n; ++i) {
    world->poses[i] = {poses.x[i], poses.y[i], poses.theta[i]};
    world->velocities[i] = {poses.v[i], poses.w[i]};
  }
}

void TakeObstacles(const obstacles_t& obstacles, agents::WorldSnapshot* world, std::vector<int>* non_finite) {
  world->obstacles.clear();
  for (const rectangle_obstacle_t& o : obstacles.obstacles) {
    agents::ObstacleView view{o.id, {o.center_x, o.center_y}, {o.width, o.height}, {o.vx, o.vy}};
    if (!view.center_m.allFinite() || !view.size_m.allFinite() || !view.velocity_mps.allFinite()) {
      if (non_finite != nullptr) non_finite->push_back(o.id);
      continue;
    }
    world->obstacles.push_back(view);
  }
}

}  // namespace dream::agent_host
