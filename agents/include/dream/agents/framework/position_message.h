#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

namespace dream::agents {

/// The Voronoi and line deployment robots' radio payload: who I am and where I am.
/// Wire format (ByteWriter): int32 id, double x m, double y m (20 bytes).
struct PositionMessage {
  int32_t id = 0;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();

  std::vector<uint8_t> Encode() const;
  /// Nothing when the payload is short, long, not finite, or names another
  /// robot than `sender_id` (a neighbour cannot speak for someone else).
  static std::optional<PositionMessage> Decode(const std::vector<uint8_t>& payload, int sender_id);
};

}  // namespace dream::agents
