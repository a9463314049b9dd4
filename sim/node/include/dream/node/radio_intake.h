#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/lcm/bad_message_log.h"
#include "dream/node/heard.h"
#include "dream/world/world.h"

namespace dream {
class radio_message_t;
}

namespace dream::node {

/// SimNode's intake of DREAM_RADIO_<id>: takes a robot's radio message into
/// the run when it is of this run, from the robot its channel names, and not
/// from a step to come; refuses (and counts in bad_messages) the rest. A robot
/// may speak kMaxPerRobotPerStep different messages per world step; a resend
/// of its last one is a repeat, not recorded again.
class RadioIntake {
 public:
  /// Different radio messages of one robot recorded per world step (its radio
  /// speaks once a step): more are refused, so a flood with the run's id
  /// cannot grow the log.
  static constexpr int kMaxPerRobotPerStep = 4;

  /// `world` and `bad_messages` must outlive the intake.
  RadioIntake(const world::World& world, int64_t run_id, lcm::BadMessageLog& bad_messages);

  /// `data`/`size`: the message as heard, which decoded to `radio`.
  Heard Take(const std::string& channel, const radio_message_t& radio, const void* data, int size);

 private:
  struct RobotRadio {
    int64_t world_step = -1;  // the world's step when `messages` were recorded
    int messages = 0;         // different radio messages recorded from this robot at that step
    size_t hash = 0;          // of the last one recorded: its resend is not recorded again
  };
  /// Why `radio` heard on `channel` is not part of the run; empty: it is.
  std::string Problem(const std::string& channel, const radio_message_t& radio) const;

  const world::World& world_;
  int64_t run_id_;
  lcm::BadMessageLog& bad_messages_;
  std::vector<RobotRadio> robots_;
};

}  // namespace dream::node
