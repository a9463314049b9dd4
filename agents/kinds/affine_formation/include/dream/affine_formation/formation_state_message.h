#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

namespace dream::affine_formation {

/// The affine formation robots' radio payload: who I am, where I am and the
/// planar velocity I am commanding (Zhao's follower law feeds neighbours'
/// velocities forward). Wire format (ByteWriter): int32 id, double x m,
/// double y m, double vx m/s, double vy m/s (36 bytes).
struct FormationStateMessage {
  int32_t id = 0;
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();

  std::vector<uint8_t> Encode() const;
  /// Nothing when the payload is short, long, not finite, or names another
  /// robot than `sender_id` (a neighbour cannot speak for someone else).
  static std::optional<FormationStateMessage> Decode(const std::vector<uint8_t>& payload, int sender_id);
};

}  // namespace dream::affine_formation
