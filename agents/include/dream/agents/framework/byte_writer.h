#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include <Eigen/Core>

namespace dream::agents {

/// Builds a radio payload: little-endian fixed-size values appended in order.
/// Pair it with ByteReader reading the same sequence.
class ByteWriter {
 public:
  ByteWriter& Int32(int32_t value) { return Raw(&value, sizeof(value)); }
  ByteWriter& Double(double value) { return Raw(&value, sizeof(value)); }
  /// x then y.
  ByteWriter& Vector2(const Eigen::Vector2d& value) { return Double(value.x()).Double(value.y()); }
  std::vector<uint8_t> Take() { return std::move(bytes_); }

 private:
  ByteWriter& Raw(const void* data, size_t size) {
    const auto* begin = static_cast<const uint8_t*>(data);
    bytes_.insert(bytes_.end(), begin, begin + size);
    return *this;
  }
  std::vector<uint8_t> bytes_;
};

}  // namespace dream::agents
