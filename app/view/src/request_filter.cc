#include "dream/view/request_filter.h"

#include <string>

namespace dream::view {
namespace {

RequestFilter::Decision Refuse(int status, std::string reason) {
  RequestFilter::Decision decision;
  decision.action = RequestFilter::Decision::Action::kRefuse;
  decision.status = status;
  decision.reason = std::move(reason);
  return decision;
}

bool IsPathChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
         c == '-' || c == '/';
}

bool IsQueryChar(char c) { return IsPathChar(c) || c == '=' || c == '&'; }

/// The page's names: the path of each asset the server has.
const char* AssetOfPath(std::string_view path) {
  if (path == "/" || path == "/index.html") return "index.html";
  if (path == "/view.js") return "view.js";
  if (path == "/view.css") return "view.css";
  if (path == "/arena.js") return "arena.js";
  if (path == "/metrics.js") return "metrics.js";
  if (path == "/export.js") return "export.js";
  return nullptr;
}

}  // namespace

RequestFilter::RequestFilter(bool loopback_only, int port, bool replay)
    : loopback_only_(loopback_only), port_(port), replay_(replay) {}

bool RequestFilter::HostAllowed(std::string_view host) const {
  if (!loopback_only_) return true;
  const std::string port = ":" + std::to_string(port_);
  for (const char* name : {"127.0.0.1", "localhost", "[::1]"}) {
    if (host == std::string(name) + port || (port_ == 80 && host == name)) return true;
  }
  return false;
}

bool RequestFilter::OriginAllowed(std::string_view origin, std::string_view host) const {
  // Browsers send Origin on every WebSocket handshake: only the page this
  // server served may open one (another site's page cannot read the run).
  return origin.empty() || origin == "http://" + std::string(host);
}

RequestFilter::Decision RequestFilter::Decide(const Request& request) const {
  if (request.version != 10 && request.version != 11) return Refuse(400, "only HTTP/1.0 and HTTP/1.1 are served");
  if (request.method != "GET")
    return Refuse(405, "only GET is served, not " + std::string(request.method.substr(0, 16)));
  if (request.target.size() > kMaxTargetChars) {
    return Refuse(414, "request target over " + std::to_string(kMaxTargetChars) + " characters");
  }
  if (request.target.empty() || request.target.front() != '/') return Refuse(400, "request target must be a path");
  if (request.host.empty()) return Refuse(400, "no Host header");
  if (!HostAllowed(request.host)) {
    return Refuse(403, "Host " + std::string(request.host.substr(0, 64)) +
                           " is not this server's (dream view answers 127.0.0.1, localhost, [::1])");
  }
  const size_t query_at = request.target.find('?');
  const std::string_view path = request.target.substr(0, query_at);
  const std::string_view query = query_at == std::string_view::npos ? "" : request.target.substr(query_at + 1);
  for (const char c : path) {
    if (!IsPathChar(c))
      return Refuse(400, "request path has a character that is not served (only A-Z a-z 0-9 . _ - /)");
  }
  for (const char c : query) {
    if (!IsQueryChar(c)) return Refuse(400, "request query has a character that is not served");
  }
  if (path.find("..") != std::string_view::npos || path.find("//") != std::string_view::npos) {
    return Refuse(400, "request path with '..' or '//': only the page's own files are served");
  }
  Decision decision;
  if (path == kWebSocketPath) {
    if (!request.websocket_upgrade) return Refuse(426, "/ws is a WebSocket: send Upgrade: websocket");
    if (!OriginAllowed(request.origin, request.host)) {
      return Refuse(403, "WebSocket from another origin (" + std::string(request.origin.substr(0, 64)) + ")");
    }
    decision.action = Decision::Action::kWebSocket;
    return decision;
  }
  if (request.websocket_upgrade) return Refuse(400, "WebSocket only on /ws");
  if (path == kRunDataPath) {
    if (!replay_) return Refuse(404, "no run to replay: this view is live");
    decision.action = Decision::Action::kRunData;
    return decision;
  }
  if (path == kExportStartPath || path == kExportStatusPath || path == kExportVideoPath) {
    if (path == kExportStartPath && !request.export_header) {
      return Refuse(403, "/export/start is asked by the page (with its X-Dream-Export header)");
    }
    decision.action = path == kExportStartPath    ? Decision::Action::kExportStart
                      : path == kExportStatusPath ? Decision::Action::kExportStatus
                                                  : Decision::Action::kExportVideo;
    decision.query = std::string(query);
    return decision;
  }
  if (const char* asset = AssetOfPath(path)) {
    decision.action = Decision::Action::kAsset;
    decision.asset = asset;
    return decision;
  }
  return Refuse(
      404,
      "not found: dream view serves /, /view.js, /arena.js, /metrics.js, /export.js, /view.css, /ws, /run.json and "
      "/export/start, /export/status, /export/video");
}

}  // namespace dream::view
