#pragma once

#include "dream/agents/framework/world_snapshot.h"

namespace dream::agents {

/// Who a robot's radio hears. Messages travel on the bus to every agent; the
/// receiving radio decides, from the world's poses (range) or a graph, which
/// senders it hears, as a real radio would. Subclasses: RangeRadio,
/// GraphRadio, RoleRadio.
class Radio {
 public:
  virtual ~Radio() = default;
  /// True when robot `self_id` hears robot `sender_id` in `world`.
  virtual bool CanHear(int self_id, int sender_id, const WorldSnapshot& world) const = 0;
  /// False for a radio that only transmits (a leader's).
  virtual bool receives() const { return true; }
  /// False for a radio that only listens.
  virtual bool publishes() const { return true; }
};

}  // namespace dream::agents
