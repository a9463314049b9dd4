#pragma once

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <utility>

#include "dream/lcm/lcm_interface.h"
#include "dream/node/node_clock.h"

namespace dream::node::testing {

/// The bus and clock SimNode tests give the node: a memq:// bus seen through
/// this one, whose time passes only while the node waits on a quiet bus. A
/// wait with nothing to hear takes its whole timeout at once (and no real
/// time); handling messages takes none. So an agent that answers is never
/// late however loaded the machine, a silent one is timed out after a fixed
/// number of quiet waits, and a real-time world steps exactly on its period.
class QuietBus : public lcm::LcmInterface {
 public:
  /// `inner` must outlive this bus; the agents of a test publish on it.
  explicit QuietBus(lcm::LcmInterface& inner) : inner_(inner), now_(std::make_shared<NodeClock::TimePoint>()) {}

  void Publish(const std::string& channel, const void* data, int size) override { inner_.Publish(channel, data, size); }
  [[nodiscard]] lcm::Subscription Subscribe(const std::string& channel_regex, lcm::RawHandler handler) override {
    return inner_.Subscribe(channel_regex, std::move(handler));
  }
  int HandleSubscriptions(int timeout_ms) override {
    const int handled = inner_.HandleSubscriptions(0);
    // At least a millisecond, so a node waiting for a moment under 1 ms away still reaches it.
    if (handled == 0) *now_ += std::chrono::milliseconds(std::max(timeout_ms, 1));
    return handled;
  }
  const std::string& url() const override { return inner_.url(); }
  long handler_failures() const override { return inner_.handler_failures(); }
  long dropped_messages() const override { return inner_.dropped_messages(); }

  /// The clock to give SimNode::set_clock; valid as long as any copy of it lives.
  NodeClock clock() const {
    return NodeClock([now = now_] { return *now; });
  }

 private:
  lcm::LcmInterface& inner_;
  std::shared_ptr<NodeClock::TimePoint> now_;
};

}  // namespace dream::node::testing
