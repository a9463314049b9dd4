#pragma once

#include <string>
#include <string_view>

namespace dream::view {

/// Decides what the view's server does with one HTTP request: serve one of
/// its own assets, open the frame WebSocket, serve the replayed run, or
/// refuse with a 4xx status. Only fixed names are served: nothing from the
/// request's path reaches the file system, so there is nothing to traverse.
class RequestFilter {
 public:
  /// The parts of a parsed request the decision needs.
  struct Request {
    std::string_view method;         ///< "GET", ...
    std::string_view target;         ///< the request target as sent, "/view.js?x=1"
    int version = 11;                ///< 10 for HTTP/1.0, 11 for HTTP/1.1
    std::string_view host;           ///< the Host header ("" when missing)
    std::string_view origin;         ///< the Origin header ("" when missing)
    bool websocket_upgrade = false;  ///< Connection: upgrade and Upgrade: websocket
    /// The X-Dream-Export header: the page's script sends it to start an
    /// export; another site's page cannot (a custom header needs CORS).
    bool export_header = false;
  };
  /// What to do.
  struct Decision {
    enum class Action { kAsset, kWebSocket, kRunData, kExportStart, kExportStatus, kExportVideo, kRefuse };
    Action action = Action::kRefuse;
    std::string asset;   ///< kAsset: the asset's name ("index.html")
    int status = 400;    ///< kRefuse: the HTTP status
    std::string reason;  ///< kRefuse: why, for the response body and the log
    std::string query;   ///< kExportStart: the request's query (after '?')
  };

  /// Request targets longer than this are refused (414).
  static constexpr size_t kMaxTargetChars = 256;
  /// The WebSocket's path.
  static constexpr std::string_view kWebSocketPath = "/ws";
  /// The replayed run's data (replay mode only).
  static constexpr std::string_view kRunDataPath = "/run.json";
  /// Video export (VideoExports): start one (its parameters in the query), its progress, the video.
  static constexpr std::string_view kExportStartPath = "/export/start";
  static constexpr std::string_view kExportStatusPath = "/export/status";
  static constexpr std::string_view kExportVideoPath = "/export/video";

  /// `loopback_only`: the server listens on a loopback address, so a Host
  /// other than 127.0.0.1, localhost or [::1] (at `port`) is refused: a web
  /// page elsewhere cannot reach it by renaming a host (DNS rebinding).
  /// `replay`: /run.json is served.
  RequestFilter(bool loopback_only, int port, bool replay);

  Decision Decide(const Request& request) const;
  /// From now on /run.json is served (a live view that became the replay of
  /// the run it drew: dream run --view at the run's end).
  void ServeRunData() { replay_ = true; }

 private:
  bool HostAllowed(std::string_view host) const;
  bool OriginAllowed(std::string_view origin, std::string_view host) const;

  bool loopback_only_;
  int port_;
  bool replay_;
};

}  // namespace dream::view
