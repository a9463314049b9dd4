#pragma once

#include <optional>
#include <string>

#include "dream/lcm/bad_message_log.h"
#include "dream/lcm/lcm_typed.h"

namespace dream::node {

/// Decodes a message heard on `channel`, or reports why it does not decode
/// (as lcm::Subscribe does) and returns false.
template <typename Message>
bool DecodeOrReport(lcm::BadMessageLog& bad_messages, const std::string& channel, const void* data, int size,
                    Message* message) {
  if (std::optional<std::string> problem = lcm::DecodeProblem(data, size, message)) {
    bad_messages.Report(
        channel, "cannot decode " + std::to_string(size) + " bytes as " + Message::getTypeName() + ": " + *problem,
        lcm::WireLayoutOf<Message>().AgentIdOf(data, size));
    return false;
  }
  return true;
}

}  // namespace dream::node
