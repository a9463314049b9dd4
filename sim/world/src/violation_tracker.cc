#include "dream/world/violation_tracker.h"

#include <cmath>

#include "dream/world/step_violation_locator.h"

namespace dream::world {

bool LocatedViolation::IsWorse(double value_m) const {
  if (std::isnan(value_m)) return false;
  if (std::isnan(worst_m)) return true;
  return kind == Kind::kCollision ? value_m < worst_m : value_m > worst_m;
}

const char* LocatedViolationKindName(LocatedViolation::Kind kind) {
  switch (kind) {
    case LocatedViolation::Kind::kBoundary:
      return "boundary";
    case LocatedViolation::Kind::kCollision:
      return "collision";
    case LocatedViolation::Kind::kObstacle:
      return "obstacle";
  }
  return "boundary";
}

void ViolationTracker::Seen(const LocatedViolation& seen, int64_t step) {
  const Key key{seen.kind, seen.robot, seen.other};
  auto it = open_.find(key);
  const bool going_on = it != open_.end() && (it->second.last_step == step || it->second.last_step == step - 1);
  if (going_on) {
    // The same violation going on (or named twice in one step): one entry
    // from its first step to this one, with the worst of its steps.
    it->second.last_step = step;
    if (it->second.index != kUnlisted) {
      LocatedViolation& entry = located_.listed[it->second.index];
      entry.last_step = step;
      if (entry.IsWorse(seen.worst_m)) entry.worst_m = seen.worst_m;
    }
    return;
  }
  Open open{kUnlisted, step};
  if (located_.listed.size() < max_listed_) {
    open.index = located_.listed.size();
    LocatedViolation entry = seen;
    entry.first_step = step;
    entry.last_step = step;
    located_.listed.push_back(entry);
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
  for (const LocatedViolation& v : placed) Seen(v, step);
  // Violations not seen at this step have ended: forget them, so the map
  // holds only what goes on now.
  for (auto it = open_.begin(); it != open_.end();) {
    it = it->second.last_step == step ? std::next(it) : open_.erase(it);
  }
}

}  // namespace dream::world
