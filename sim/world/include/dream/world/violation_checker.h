#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "dream/world/obstacle_state.h"
#include "dream/world/pose2.h"
#include "dream/world/step_events.h"
#include "dream/world/unicycle_command.h"
#include "dream/world/violation_counts.h"
#include "dream/world/world_params.h"

namespace dream::world {

class PairwiseRules;

// The Robotarium's validation rules on poses that come from elsewhere (a lab
// recording, a run log), without any physics: the same counts UnicycleWorld
// keeps (see its Step(), rule 1), from the same geometry code.
class ViolationChecker {
 public:
  // Throws std::invalid_argument if params are invalid.
  ViolationChecker(const WorldParams& params, int num_robots);
  ~ViolationChecker();
  ViolationChecker(ViolationChecker&&) noexcept;
  ViolationChecker& operator=(ViolationChecker&&) noexcept;

  // Validates the poses of step `step` and the velocities commanded for it
  // (nullptr: no actuator check) against obstacles at that step, adds to
  // counts() and lists who did what in last_step_events(). Poses must be
  // finite and num_robots long (std::invalid_argument otherwise).
  void Check(int64_t step, const std::vector<Pose2>& poses, const std::vector<UnicycleCommand>* commands,
             const std::vector<ObstacleState>& obstacles);

  const ViolationCounts& counts() const { return counts_; }
  const StepEvents& last_step_events() const { return events_; }

 private:
  WorldParams params_;
  std::size_t num_robots_;
  ViolationCounts counts_{};
  StepEvents events_{};
  std::unique_ptr<PairwiseRules> rules_;
};

}  // namespace dream::world
