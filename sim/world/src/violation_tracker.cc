#include "dream/world/violation_tracker.h"

namespace dream::world {

const char* LocatedViolationKindName(LocatedViolation::Kind kind) {
  switch (kind) {
    case LocatedViolation::Kind::kBoundary: return "boundary";
    case LocatedViolation::Kind::kCollision: return "collision";
    case LocatedViolation::Kind::kObstacle: return "obstacle";
  }
  return "boundary";
}

void ViolationTracker::Seen(const Key& key, int64_t step, double x_m, double y_m) {
  auto it = open_.find(key);
  if (it != open_.end() && it->second.last_step == step) return;  // named twice in one step
  if (it != open_.end() && it->second.last_step == step - 1) {
    // The same violation going on: one entry from its first step to this one.
    it->second.last_step = step;
    if (it->second.index != kUnlisted) located_.listed[it->second.index].last_step = step;
    return;
  }
  Open open{kUnlisted, step};
  if (located_.listed.size() < max_listed_) {
    open.index = located_.listed.size();
    located_.listed.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), step, step, x_m, y_m});
  } else {
    ++located_.unlisted;
  }
  open_[key] = open;
}

void ViolationTracker::Add(const StepEvents& events, const std::vector<Pose2>& poses) {
  const int n = static_cast<int>(poses.size());
  auto known = [n](int robot) { return robot >= 0 && robot < n; };
  for (const int robot : events.out_of_bounds_robot_ids) {
    if (!known(robot)) continue;
    const Pose2& at = poses[static_cast<size_t>(robot)];
    Seen({LocatedViolation::Kind::kBoundary, robot, -1}, events.step, at.x_m, at.y_m);
  }
  for (const StepEvents::RobotPair& pair : events.colliding_pairs) {
    if (!known(pair.first_robot_id) || !known(pair.second_robot_id)) continue;
    const Pose2& a = poses[static_cast<size_t>(pair.first_robot_id)];
    const Pose2& b = poses[static_cast<size_t>(pair.second_robot_id)];
    Seen({LocatedViolation::Kind::kCollision, pair.first_robot_id, pair.second_robot_id}, events.step,
         (a.x_m + b.x_m) / 2, (a.y_m + b.y_m) / 2);
  }
  for (const StepEvents::RobotObstacleContact& contact : events.obstacle_contacts) {
    if (!known(contact.robot_id)) continue;
    const Pose2& at = poses[static_cast<size_t>(contact.robot_id)];
    Seen({LocatedViolation::Kind::kObstacle, contact.robot_id, contact.obstacle_id}, events.step, at.x_m, at.y_m);
  }
  // Violations not seen at this step have ended: forget them, so the map
  // holds only what goes on now.
  for (auto it = open_.begin(); it != open_.end();) {
    it = it->second.last_step == events.step ? std::next(it) : open_.erase(it);
  }
}

}  // namespace dream::world
