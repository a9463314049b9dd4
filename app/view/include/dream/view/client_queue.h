#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>

namespace dream::view {

/// The messages waiting for one browser: at most `capacity`, and when a new
/// one arrives at a full queue the oldest is dropped (and counted). A slow or
/// vanished browser so loses frames, never stalls the run or grows memory.
/// Not thread-safe: each queue belongs to its connection's thread.
class ClientQueue {
 public:
  using Message = std::shared_ptr<const std::string>;

  /// @throws std::invalid_argument when `capacity` is 0.
  explicit ClientQueue(size_t capacity);

  /// Adds `message` at the back; drops the front first when full.
  void Push(Message message);
  /// Takes the front message; null when empty.
  Message Pop();

  size_t size() const { return messages_.size(); }
  bool empty() const { return messages_.empty(); }
  size_t capacity() const { return capacity_; }
  /// Messages dropped so far because the queue was full.
  int64_t dropped() const { return dropped_; }

 private:
  size_t capacity_;
  std::deque<Message> messages_;
  int64_t dropped_ = 0;
};

}  // namespace dream::view
