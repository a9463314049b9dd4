#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace dream::run_log {

/// One LCM payload as JSON, for `dream log echo`: the DREAM message types
/// (lcmtypes/dream/*.lcm) are told apart by their fingerprint, the payload's
/// first 8 bytes, as lcm-spy does, so DREAM_LAB_CMD_<id> decodes like
/// DREAM_CMD_<id>. Bytes are checked by lcm::DecodeProblem (the message's
/// WireLayout first), so a forged count costs no memory.
class MessageJson {
 public:
  enum class Outcome {
    kDecoded,      ///< type() and fields() hold the message
    kUnknownType,  ///< a fingerprint no DREAM type has (another program's channel)
    kUndecodable,  ///< a DREAM fingerprint but bytes that are not one whole message; problem() says why
  };

  /// Decodes `data` (the payload of one log event).
  explicit MessageJson(const std::vector<uint8_t>& data);

  Outcome outcome() const { return outcome_; }
  /// "robot_poses_t"; empty unless decoded or undecodable.
  const std::string& type() const { return type_; }
  /// The message's fields by their .lcm names, in order; byte arrays (a
  /// radio payload) as a lowercase hex string.
  const nlohmann::ordered_json& fields() const { return fields_; }
  /// Why the bytes are not a message (kUndecodable), or whose they are not
  /// (kUnknownType: a fingerprint no DREAM type has, or too few bytes).
  const std::string& problem() const { return problem_; }

 private:
  Outcome outcome_ = Outcome::kUnknownType;
  std::string type_;
  nlohmann::ordered_json fields_;
  std::string problem_;
};

}  // namespace dream::run_log
