#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/lcm/bad_message_log.h"
#include "dream/node/heard.h"
#include "dream/world/world.h"

namespace dream {
class drawing_t;
}

namespace dream::node {

/// SimNode's intake of DREAM_DRAW_<id>: takes what a robot's controller drew
/// into the run's log when it is of this run, from the robot its channel
/// names, not from a step to come, and a drawing by lcm::DrawingShapes (kinds,
/// points, text, numbers within drawing_t's bounds); refuses (and counts in
/// bad_messages) the rest. The world never reads a drawing: it cannot change
/// the run. A resend of a robot's last drawing is a repeat, not recorded again.
class DrawingIntake {
 public:
  /// Different drawings of one robot recorded per world step (its agent sends
  /// at most one a step): more are refused, so a flood cannot grow the log.
  static constexpr int kMaxPerRobotPerStep = 2;

  /// `world` and `bad_messages` must outlive the intake.
  DrawingIntake(const world::World& world, int64_t run_id, lcm::BadMessageLog& bad_messages);

  /// `data`/`size`: the message as heard (one that does not decode as a
  /// drawing_t is refused, as SimNode refuses every agent message that does not).
  Heard Take(const std::string& channel, const void* data, int size);

 private:
  struct RobotDrawings {
    int64_t world_step = -1;  // the world's step when `drawings` were recorded
    int drawings = 0;         // different drawings recorded from this robot at that step
    size_t hash = 0;          // of the last one recorded: its resend is not recorded again
  };
  /// Why `drawing` heard on `channel` is not part of the run; empty: it is.
  std::string Problem(const std::string& channel, const drawing_t& drawing) const;

  const world::World& world_;
  int64_t run_id_;
  lcm::BadMessageLog& bad_messages_;
  std::vector<RobotDrawings> robots_;
};

}  // namespace dream::node
