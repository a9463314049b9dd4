#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_interface.h"
#include "dream/lcm/wire_layout_of.h"

namespace dream::lcm {

/// Encodes `message` (an lcm-gen C++ type) and publishes it on `channel`.
template <typename Message>
void Publish(LcmInterface& lcm, const std::string& channel, const Message& message) {
  const int size = message.getEncodedSize();
  std::vector<uint8_t> buffer(static_cast<size_t>(size));
  if (message.encode(buffer.data(), 0, size) != size) {
    throw std::runtime_error("cannot encode message for channel " + channel);
  }
  lcm.Publish(channel, buffer.data(), size);
}

/// Decodes `size` bytes into `message`; returns why they are not one complete
/// `Message` (wrong fingerprint, a count over its limit or over the bytes,
/// truncated, trailing garbage), or nothing on success. The bytes are checked
/// against the type's WireLayout first, so the lcm-gen decoder only ever sees
/// counts the bytes can hold: a forged message costs no more memory than its
/// own size. Every decode of a dream message goes through here.
template <typename Message>
std::optional<std::string> DecodeProblem(const void* data, int size, Message* message) {
  if (std::optional<std::string> problem = WireLayoutOf<Message>().Problem(data, size)) return problem;
  if (message->decode(data, 0, size) != size) return std::string("refused by the lcm-gen decoder");
  return std::nullopt;
}

/// DecodeProblem() as a yes or no.
template <typename Message>
bool Decode(const void* data, int size, Message* message) {
  return !DecodeProblem(data, size, message).has_value();
}

/// Subscribes `handler` to decoded `Message`s on channels matching
/// `channel_regex`. Undecodable messages are reported to `bad_messages`
/// (naming the channel, the expected type, what was wrong and, when the bytes
/// reach it, the sender's agent_id) and dropped. The handler is called until the
/// returned Subscription is destroyed.
template <typename Message>
[[nodiscard]] Subscription Subscribe(LcmInterface& lcm, const std::string& channel_regex,
                                     std::function<void(const std::string& channel, const Message&)> handler,
                                     BadMessageLog& bad_messages) {
  return lcm.Subscribe(channel_regex, [handler = std::move(handler), &bad_messages](const std::string& channel,
                                                                                    const void* data, int size) {
    Message message;
    if (std::optional<std::string> problem = DecodeProblem(data, size, &message)) {
      bad_messages.Report(
          channel, "cannot decode " + std::to_string(size) + " bytes as " + Message::getTypeName() + ": " + *problem,
          WireLayoutOf<Message>().AgentIdOf(data, size));
      return;
    }
    handler(channel, message);
  });
}

/// Subscribe() with a member function of `owner` as the handler, the usual
/// case for a node: Subscribe(lcm_, kPosesChannel, this, &AgentHost::OnPoses, bad_messages_).
template <typename Owner, typename Message>
[[nodiscard]] Subscription Subscribe(LcmInterface& lcm, const std::string& channel_regex, Owner* owner,
                                     void (Owner::*on_message)(const std::string& channel, const Message&),
                                     BadMessageLog& bad_messages) {
  return Subscribe<Message>(
      lcm, channel_regex,
      [owner, on_message](const std::string& channel, const Message& message) {
        (owner->*on_message)(channel, message);
      },
      bad_messages);
}

}  // namespace dream::lcm
