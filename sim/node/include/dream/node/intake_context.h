#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dream/config/sim_node_options.h"
#include "dream/lcm/bad_message_log.h"
#include "dream/node/node_clock.h"
#include "dream/node/robot_slot.h"
#include "dream/world/world.h"

namespace dream::node {

/// What SimNode's intakes of the agents' messages (CommandIntake,
/// BusyIntake) share: the run they check messages against and what they
/// count and tell. SimNode builds it once; each intake keeps a copy, and
/// everything referred to must outlive the intakes.
struct IntakeContext {
  /// Called with the run id of another world a message answers, and its channel.
  using OtherWorldSeen = std::function<void(int64_t run_id, const std::string& seen_on)>;

  world::World& world;
  const config::SimNodeOptions& options;
  int64_t run_id;
  /// One slot per robot of `world`.
  std::vector<RobotSlot>& robots;
  lcm::BadMessageLog& bad_messages;
  /// Says when a message was heard.
  const NodeClock& clock;
  OtherWorldSeen other_world_seen;
};

}  // namespace dream::node
