#pragma once

#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace dream::python_host {

/// Frames between dream and the process that hosts its Python controllers
/// (PythonHostProcess), over one stream socket: a kind byte, the channel's and
/// the data's lengths (big-endian uint32), the channel, the data. The other
/// side may be a controller gone wrong, so what is read is bounded and a
/// malformed frame is an error, never an allocation of its claimed size.
class RelayLink {
 public:
  static constexpr size_t kMaxChannelBytes = 1024;
  /// Far above any message of a run (a 128-robot DREAM_POSES is 5 KB).
  static constexpr size_t kMaxDataBytes = size_t{1} << 27;

  struct Frame {
    char kind = 0;
    std::string channel;
    std::string data;
  };

  /// Takes `fd`, a connected stream socket; closes it when destroyed.
  explicit RelayLink(int fd);
  ~RelayLink();
  RelayLink(const RelayLink&) = delete;
  RelayLink& operator=(const RelayLink&) = delete;

  int fd() const { return fd_; }

  /// Writes a whole frame, blocking; false once the other side is gone.
  /// Thread safe.
  bool Send(char kind, const std::string& channel, const void* data, size_t size);
  bool Send(char kind, const std::string& channel = "", const std::string& data = "") {
    return Send(kind, channel, data.data(), data.size());
  }

  /// Appends a whole frame to `out` (for a caller that writes it later).
  static void Encode(char kind, const std::string& channel, const void* data, size_t size, std::string* out);

  /// Blocks for one frame: false at the end of the stream.
  /// @throws std::runtime_error on a malformed frame.
  bool Receive(Frame* frame);

  enum class Read { kOpen, kClosed, kMalformed };
  /// Reads what the socket holds now, without blocking, and appends the
  /// complete frames to `frames`; kMalformed with `problem` set when the
  /// bytes are no frame.
  Read ReadAvailable(std::vector<Frame>* frames, std::string* problem);

  /// Ends the stream both ways (the other side reads its end).
  void Shutdown();

 private:
  /// A whole frame at the front of buffer_ into `frame`: 1 taken, 0 not yet
  /// complete, -1 malformed (`problem` says why).
  int TakeFrame(Frame* frame, std::string* problem);

  int fd_;
  std::mutex send_mutex_;
  std::string buffer_;  // bytes read, not yet framed
};

}  // namespace dream::python_host
