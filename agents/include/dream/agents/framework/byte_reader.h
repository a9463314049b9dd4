#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace dream::agents {

/// Reads a radio payload written by ByteWriter. Never throws and never reads
/// past the end: a short or malformed payload makes ok() false, so a robot
/// can drop a neighbour's bad message instead of crashing on it.
class ByteReader {
 public:
  explicit ByteReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}

  int32_t Int32() { return Read<int32_t>(); }
  /// Non-finite values also make ok() false: no payload should carry them.
  double Double() {
    const double value = Read<double>();
    if (!std::isfinite(value)) ok_ = false;
    return value;
  }
  /// x then y, as ByteWriter::Vector2 writes them.
  Eigen::Vector2d Vector2() {
    const double x = Double();
    return {x, Double()};
  }

  /// True when every read so far was complete and valid.
  bool ok() const { return ok_; }
  /// True when ok() and the whole payload was consumed.
  bool done() const { return ok_ && position_ == bytes_.size(); }

 private:
  template <typename T>
  T Read() {
    T value{};
    if (!ok_ || bytes_.size() - position_ < sizeof(T)) {
      ok_ = false;
      return value;
    }
    std::memcpy(&value, bytes_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    return value;
  }

  const std::vector<uint8_t>& bytes_;
  size_t position_ = 0;
  bool ok_ = true;
};

}  // namespace dream::agents
