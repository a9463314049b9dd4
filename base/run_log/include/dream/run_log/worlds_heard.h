#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"

namespace dream::run_log {

/// The worlds whose messages a log holds, by run id, as RunLog reads it. A
/// run's own log holds one; a recording of the bus (lcm-logger) may hold the
/// world's resends (it publishes a step again while it waits for answers)
/// and a second world's messages. Each world keeps its poses in log order
/// with resends (the same message again) left out, so a recording and the
/// run's own log give the same steps. At most kMaxWorlds run ids are kept;
/// messages of further ones are counted, not kept.
class WorldsHeard {
 public:
  struct World {
    int64_t run_id = 0;
    std::vector<robot_poses_t> poses;  ///< resends left out
    std::vector<int64_t> events;       ///< the log event of each of poses
    std::vector<robot_poses_t> measured;
    std::optional<run_status_t> last_status;
    int64_t resends = 0;  ///< DREAM_POSES and DREAM_MEASURED_POSES heard again and left out
  };
  static constexpr size_t kMaxWorlds = 16;

  void AddPoses(robot_poses_t poses, int64_t event_index);
  void AddMeasured(robot_poses_t measured);
  void AddStatus(run_status_t status);

  /// The world a log is of: the one with the most steps, the first heard on
  /// a tie (a second world idling at step 0 beside a run is not the run);
  /// null when no world was heard.
  World* Followed();
  const std::vector<World>& worlds() const { return worlds_; }
  /// Messages of run ids beyond kMaxWorlds, not kept.
  int64_t dropped_messages() const { return dropped_messages_; }

 private:
  /// The world of `run_id`, heard from now on; null when kMaxWorlds are kept.
  World* Of(int64_t run_id);

  std::vector<World> worlds_;
  int64_t dropped_messages_ = 0;
};

}  // namespace dream::run_log
