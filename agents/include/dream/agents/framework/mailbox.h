#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "dream/agents/framework/radio.h"
#include "dream/agents/framework/radio_message.h"

namespace dream::agents {

/// Radio impairments, so users can test robustness.
struct RadioLinkParams {
  double loss_probability = 0.0;  ///< chance each message is lost for each receiver, [0, 1)
  int delay_steps = 0;            ///< extra steps before a message can be heard, >= 0
  bool IsValid(std::string* error) const;
};

/// A robot's incoming radio traffic. Like the thesis's message board it keeps
/// the latest message of every sender; a message sent at step k can be heard
/// from step k + 1 + delay_steps. Loss is decided by a hash of (seed, sender,
/// step), not by arrival order, so runs repeat exactly across process layouts.
class Mailbox {
 public:
  /// @throws std::invalid_argument when params are invalid.
  Mailbox(const RadioLinkParams& params, uint64_t seed);

  /// Stores `message` unless the link loses it.
  void Post(RadioMessage message);

  /// The latest message, from each sender `radio` hears at `world`'s step,
  /// that can be heard by then; ordered by sender id.
  std::vector<RadioMessage> Heard(const Radio& radio, int self_id, const WorldSnapshot& world) const;

  long lost_messages() const { return lost_; }

 private:
  RadioLinkParams params_;
  uint64_t seed_;
  // Per sender, messages by sent step; only the newest few are kept.
  std::map<int, std::map<int64_t, RadioMessage>> by_sender_;
  long lost_ = 0;
};

}  // namespace dream::agents
