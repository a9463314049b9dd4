#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace dream::view {

class VideoExports;

/// The view's HTTP and WebSocket server (Boost.Beast) on one thread of its
/// own: serves the page's embedded assets, /run.json in replay, and a
/// WebSocket (/ws) to each browser, which gets the setup, the latest frame,
/// then every frame Broadcast() while it keeps up (a bounded ClientQueue per
/// browser: a slow one loses the oldest frames).
///
/// Every size is bounded: the request line and headers (kMaxHeaderBytes),
/// no request body, what a browser may send on its WebSocket
/// (kMaxClientMessageBytes), the browsers at once (kMaxClients), the HTTP
/// connections at once (kMaxHttpConnections), 15 s to send a request. Requests
/// that break a rule (RequestFilter, or that do not parse) get a 4xx and
/// their connection is closed.
class ViewServer {
 public:
  struct Options {
    std::string bind_address = "127.0.0.1";
    int port = 8077;          ///< 0: any free port (port() says which)
    bool replay = false;      ///< serve /run.json
    size_t queue_frames = 8;  ///< each browser's ClientQueue
  };
  static constexpr size_t kMaxHeaderBytes = 8192;
  static constexpr size_t kMaxClientMessageBytes = 4096;
  static constexpr size_t kMaxClients = 64;
  /// HTTP connections at once; more are closed as they arrive.
  static constexpr size_t kMaxHttpConnections = 256;

  /// Listens on the address and port, and starts the server's thread.
  /// @throws std::runtime_error naming the address and port when it cannot
  ///         (in use, not an address of this machine, not an address).
  explicit ViewServer(const Options& options);
  /// Closes every connection and joins the thread.
  ~ViewServer();
  ViewServer(const ViewServer&) = delete;
  ViewServer& operator=(const ViewServer&) = delete;

  /// The port it listens on.
  int port() const;
  /// "http://127.0.0.1:8077/".
  std::string url() const;

  /// What each browser gets first when it connects (SetupJson).
  void SetSetup(std::string setup_json);
  /// The replayed run (RunReplayJson), served on /run.json.
  void SetRunData(std::string run_json);
  /// Turns a live server into the replay of the run it showed, at the same
  /// URL: /run.json serves `run_json` from now on, and every browser gets
  /// `setup_json` (a replay's SetupJson), now and when it connects, and no
  /// live frame after it. Call it once no more frames are broadcast. Thread-safe.
  void ServeReplay(std::string setup_json, std::string run_json);
  /// The video exports /export/* serves (a replay's run); none (the default,
  /// and live): /export/start is refused, saying to export the replay. Thread-safe.
  void SetVideoExports(std::shared_ptr<VideoExports> exports);
  /// Sends `frame_json` to every browser (queued per browser; never waits),
  /// and keeps it for browsers that connect later. Thread-safe.
  void Broadcast(std::string frame_json);

  /// Text messages browsers send on their WebSocket (at most
  /// kMaxClientMessageBytes each) are handed to `handler` on the server's
  /// thread; none (empty) drops them. Once this returns, the handler it
  /// replaced is not running and never called again. Thread-safe.
  void SetClientMessageHandler(std::function<void(const std::string&)> handler);

  /// Browsers connected now, and frames dropped for slow ones so far.
  size_t clients() const;
  int64_t dropped_frames() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dream::view
