#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "dream/world/located_violation.h"
#include "dream/world/pose2.h"
#include "dream/world/step_events.h"

namespace dream::world {

/// Follows the violations a ViolationChecker (or UnicycleWorld) finds step by
/// step and places them: each new violation becomes a LocatedViolation at its
/// first step; the same violation by the same robots at the next step only
/// moves its last step on. At most `max_listed` entries are kept, the rest
/// counted, so a run that breaks a rule at every step costs a bounded list.
class ViolationTracker {
 public:
  static constexpr size_t kDefaultMaxListed = 100;

  explicit ViolationTracker(size_t max_listed = kDefaultMaxListed) : max_listed_(max_listed) {}

  /// Adds the events of one step, checked on `poses` (the same poses the
  /// events' robot ids index). Steps must come in increasing order; an event
  /// naming a robot outside `poses` is ignored (it cannot be placed).
  void Add(const StepEvents& events, const std::vector<Pose2>& poses);
  /// Adds the violations of step `step` already placed (PlaceViolations,
  /// StepViolationLocator); a step with none still ends those going on.
  void AddPlaced(int64_t step, const std::vector<LocatedViolation>& placed);

  const LocatedViolations& located() const { return located_; }

 private:
  using Key = std::tuple<LocatedViolation::Kind, int, int>;  // kind, robot, other
  /// An entry still going on at the last step: its index in listed (or kUnlisted).
  struct Open {
    size_t index = 0;
    int64_t last_step = 0;
  };
  static constexpr size_t kUnlisted = static_cast<size_t>(-1);

  void Seen(const LocatedViolation& seen, int64_t step);

  size_t max_listed_;
  LocatedViolations located_;
  std::map<Key, Open> open_;              // bounded by the violations of one step
  std::vector<LocatedViolation> placed_;  // one step's, reused
};

}  // namespace dream::world
