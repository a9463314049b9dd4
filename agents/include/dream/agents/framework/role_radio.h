#pragma once

#include "dream/agents/framework/communication_graph.h"
#include "dream/agents/framework/radio.h"

namespace dream::agents {

/// Leader/follower radios (the affine formation experiment): a leader only
/// publishes; a follower publishes and hears its graph neighbours, leaders
/// and followers alike.
class RoleRadio final : public Radio {
 public:
  enum class Role { kLeader, kFollower };
  RoleRadio(Role role, CommunicationGraph graph);
  bool CanHear(int self_id, int sender_id, const WorldSnapshot& world) const override;
  bool receives() const override { return role_ == Role::kFollower; }

 private:
  Role role_;
  CommunicationGraph graph_;
};

}  // namespace dream::agents
