#include "dream/node/world_messages.h"

namespace dream::node {

void WorldMessages::Fill(const world::World& world, std::vector<world::ObstacleState>* scratch,
                         obstacles_t* obstacles) {
  obstacles->step = world.step();
  world.GetObstacleStates(scratch);
  obstacles->obstacles.clear();
  for (const world::ObstacleState& s : *scratch) {
    obstacles->obstacles.push_back(
        rectangle_obstacle_t{s.id, s.center_x_m, s.center_y_m, s.width_m, s.height_m, s.vx_mps, s.vy_mps});
  }
  obstacles->num_obstacles = static_cast<int32_t>(obstacles->obstacles.size());
}

void WorldMessages::Fill(const world::World& world, robot_poses_t* poses) {
  poses->step = world.step();
  poses->num_robots = world.num_robots();
  poses->x.clear();
  poses->y.clear();
  poses->theta.clear();
  poses->v.clear();
  poses->w.clear();
  for (const world::Pose2& pose : world.poses()) {
    poses->x.push_back(pose.x_m);
    poses->y.push_back(pose.y_m);
    poses->theta.push_back(pose.theta_rad);
  }
  // After Step() the held velocities are the saturated ones the robots just
  // drove with.
  for (const world::UnicycleCommand& velocity : world.velocities()) {
    poses->v.push_back(world.step() > 0 ? velocity.v_mps : 0.0);
    poses->w.push_back(world.step() > 0 ? velocity.w_radps : 0.0);
  }
}

void WorldMessages::Fill(const world::World& world, run_status_t* status) {
  status->step = world.step();
  status->num_robots = world.num_robots();
  const world::ViolationCounts& counts = world.violations();
  status->boundary_errors = counts.boundary_errors;
  status->collision_errors = counts.collision_errors;
  status->actuator_errors = counts.actuator_errors;
  status->obstacle_collisions = counts.obstacle_collisions;
}

}  // namespace dream::node
