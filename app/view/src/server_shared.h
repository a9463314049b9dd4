#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "dream/view/request_filter.h"
#include "dream/view/video_exports.h"

namespace dream::view {

class WebSocketSession;

/// What the server's connections share. Touched only on the server's thread,
/// except the atomic counters (read by ViewServer from any thread).
struct ServerShared {
  ServerShared(RequestFilter request_filter, size_t frames_per_client)
      : filter(std::move(request_filter)), queue_frames(frames_per_client) {}

  RequestFilter filter;
  size_t queue_frames;
  std::shared_ptr<const std::string> setup;         ///< sent first to each browser
  std::shared_ptr<const std::string> latest_frame;  ///< sent next, so a new browser draws at once
  std::shared_ptr<const std::string> run_data;      ///< /run.json (replay)
  std::shared_ptr<VideoExports> exports;            ///< /export/* (a replay's; none live)
  std::vector<std::weak_ptr<WebSocketSession>> clients;
  std::atomic<size_t> client_count{0};
  /// HTTP connections open now (a WebSocket's counts here until its upgrade).
  std::atomic<size_t> http_connections{0};
  std::atomic<int64_t> dropped_frames{0};
  /// WebSocket writes started and not completed (the server waits for them, briefly, when it stops).
  std::atomic<int> writes_in_flight{0};

  /// What a page sends (ViewServer::SetClientMessageHandler), under its own
  /// lock: the handler is set from other threads and called on the server's.
  std::mutex client_message_mutex;
  std::function<void(const std::string&)> on_client_message;
  /// Hands a page's message to the handler, if any; what it throws is dropped.
  void HandClientMessage(const std::string& message) {
    std::lock_guard<std::mutex> lock(client_message_mutex);
    if (!on_client_message) return;
    try {
      on_client_message(message);
    } catch (...) {  // a page's message is never worth the server's thread
    }
  }
};

}  // namespace dream::view
