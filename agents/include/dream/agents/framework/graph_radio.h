#pragma once

#include "dream/agents/framework/communication_graph.h"
#include "dream/agents/framework/radio.h"

namespace dream::agents {

/// Hears exactly its neighbours in a communication graph, wherever they are.
class GraphRadio final : public Radio {
 public:
  explicit GraphRadio(CommunicationGraph graph);
  bool CanHear(int self_id, int sender_id, const WorldSnapshot& world) const override;

 private:
  CommunicationGraph graph_;
};

}  // namespace dream::agents
