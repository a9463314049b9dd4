#pragma once

#include <functional>
#include <string>

#include "dream/lcm/subscription.h"

namespace dream::lcm {

/// Receives one raw message: the channel it arrived on and its encoded bytes.
using RawHandler = std::function<void(const std::string& channel, const void* data, int size)>;

/// A small transport interface over LCM, modelled on Drake's DrakeLcmInterface:
/// the sim node, agent hosts and bridge talk to this, never to lcm::LCM, so
/// tests can swap the transport by URL (memq://, udpm://) without code changes.
/// Typed publish/subscribe lives in lcm_typed.h on top of it.
class LcmInterface {
 public:
  virtual ~LcmInterface() = default;

  /// Sends `size` bytes on `channel`. Throws std::runtime_error if LCM refuses.
  virtual void Publish(const std::string& channel, const void* data, int size) = 0;

  /// Calls `handler` for every message whose channel matches the regular
  /// expression `channel_regex` (LCM semantics: the whole name must match).
  /// Exceptions thrown by `handler` are caught, logged and counted; they never
  /// reach LCM's C code. The handler is called until the returned Subscription
  /// is destroyed: keep it as long as the handler's captures live.
  [[nodiscard]] virtual Subscription Subscribe(const std::string& channel_regex, RawHandler handler) = 0;

  /// Dispatches received messages to their handlers, waiting up to
  /// `timeout_ms` for the first one (0 polls). Returns the number of messages
  /// handled (0 on timeout). Must not be called from inside a handler.
  virtual int HandleSubscriptions(int timeout_ms) = 0;

  /// The URL this transport was opened with.
  virtual const std::string& url() const = 0;

  /// Handler exceptions caught so far.
  virtual long handler_failures() const = 0;

  /// Messages the transport dropped so far because its queue was full
  /// (memq://); a transport without such a queue drops none here.
  virtual long dropped_messages() const = 0;
};

}  // namespace dream::lcm
