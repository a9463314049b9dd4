#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_interface.h"

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

/// Decodes `size` bytes into `message`; false when the bytes are not a
/// complete `Message` (wrong fingerprint, truncated, trailing garbage).
template <typename Message>
bool Decode(const void* data, int size, Message* message) {
  return message->decode(data, 0, size) == size;
}

/// Subscribes `handler` to decoded `Message`s on channels matching
/// `channel_regex`. Undecodable messages are reported to `bad_messages`
/// (naming the channel and the expected type) and dropped.
template <typename Message>
void Subscribe(LcmInterface& lcm, const std::string& channel_regex,
               std::function<void(const std::string& channel, const Message&)> handler,
               BadMessageLog& bad_messages) {
  lcm.Subscribe(channel_regex, [handler = std::move(handler), &bad_messages](
                                   const std::string& channel, const void* data, int size) {
    Message message;
    if (!Decode(data, size, &message)) {
      bad_messages.Report(channel, "cannot decode " + std::to_string(size) + " bytes as " +
                                       Message::getTypeName());
      return;
    }
    handler(channel, message);
  });
}

}  // namespace dream::lcm
