#include "dream/world/violation_tracker.h"

#include "dream/world/step_violation_locator.h"

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
  placed_.clear();
  PlaceViolations(events, poses, &placed_);
  AddPlaced(events.step, placed_);
}

void ViolationTracker::AddPlaced(int64_t step, const std::vector<LocatedViolation>& placed) {
  for (const LocatedViolation& v : placed) Seen({v.kind, v.robot, v.other}, step, v.x_m, v.y_m);
  // Violations not seen at this step have ended: forget them, so the map
  // holds only what goes on now.
  for (auto it = open_.begin(); it != open_.end();) {
    it = it->second.last_step == step ? std::next(it) : open_.erase(it);
  }
}

}  // namespace dream::world
