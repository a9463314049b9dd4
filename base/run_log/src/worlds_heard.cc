#include "dream/run_log/worlds_heard.h"

#include <utility>

namespace dream::run_log {
namespace {

// The world sends a step again, unchanged, while it waits for answers: the
// same step, time and poses.
bool SameMessage(const robot_poses_t& a, const robot_poses_t& b) {
  return a.step == b.step && a.utime == b.utime && a.num_robots == b.num_robots && a.x == b.x && a.y == b.y &&
         a.theta == b.theta && a.v == b.v && a.w == b.w;
}

}  // namespace

WorldsHeard::World* WorldsHeard::Of(int64_t run_id) {
  for (World& world : worlds_) {
    if (world.run_id == run_id) return &world;
  }
  if (worlds_.size() >= kMaxWorlds) {
    ++dropped_messages_;
    return nullptr;
  }
  World& world = worlds_.emplace_back();
  world.run_id = run_id;
  return &world;
}

void WorldsHeard::AddPoses(robot_poses_t poses, int64_t event_index) {
  World* world = Of(poses.run_id);
  if (world == nullptr) return;
  if (!world->poses.empty() && SameMessage(world->poses.back(), poses)) {
    ++world->resends;
    return;
  }
  world->poses.push_back(std::move(poses));
  world->events.push_back(event_index);
}

void WorldsHeard::AddMeasured(robot_poses_t measured) {
  World* world = Of(measured.run_id);
  if (world == nullptr) return;
  if (!world->measured.empty() && SameMessage(world->measured.back(), measured)) {
    ++world->resends;
    return;
  }
  world->measured.push_back(std::move(measured));
}

void WorldsHeard::AddStatus(run_status_t status) {
  World* world = Of(status.run_id);
  if (world != nullptr) world->last_status = std::move(status);
}

WorldsHeard::World* WorldsHeard::Followed() {
  World* followed = nullptr;
  for (World& world : worlds_) {
    if (followed == nullptr || world.poses.size() > followed->poses.size()) followed = &world;
  }
  return followed;
}

}  // namespace dream::run_log
