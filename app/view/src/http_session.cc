#include "http_session.h"

#include <spdlog/spdlog.h>

#include <boost/beast/websocket.hpp>
#include <chrono>
#include <utility>

#include "dream/view/view_assets.h"
#include "dream/view/view_server.h"
#include "websocket_session.h"

namespace dream::view {

namespace beast = boost::beast;
namespace http = beast::http;

namespace {
constexpr std::chrono::seconds kRequestTimeout{15};  // a connection that sends nothing is closed

std::string_view View(beast::string_view text) { return std::string_view(text.data(), text.size()); }
}  // namespace

HttpSession::HttpSession(boost::asio::ip::tcp::socket socket, ServerShared& shared)
    : stream_(std::move(socket)), buffer_(ViewServer::kMaxHeaderBytes), shared_(shared) {
  shared_.http_connections.fetch_add(1);
}

HttpSession::~HttpSession() { shared_.http_connections.fetch_sub(1); }

void HttpSession::Read() {
  parser_.emplace();
  parser_->header_limit(ViewServer::kMaxHeaderBytes);
  parser_->body_limit(0);  // the view takes no request bodies
  stream_.expires_after(kRequestTimeout);
  http::async_read(stream_, buffer_, *parser_,
                   [self = shared_from_this()](beast::error_code error, size_t) { self->OnRead(error); });
}

void HttpSession::OnRead(beast::error_code error) {
  if (error == http::error::end_of_stream || error == beast::error::timeout ||
      error == boost::asio::error::connection_reset || error == boost::asio::error::operation_aborted) {
    Close();
    return;
  }
  if (error == http::error::header_limit || error == http::error::buffer_overflow) {
    Refuse(431, "request line and headers over " + std::to_string(ViewServer::kMaxHeaderBytes) + " bytes");
    return;
  }
  if (error) {
    Refuse(400, "malformed request: " + error.message());
    return;
  }
  Serve(parser_->get());
}

void HttpSession::Serve(const http::request<http::empty_body>& request) {
  RequestFilter::Request facts;
  const std::string method(request.method_string());
  facts.method = method;
  facts.target = View(request.target());
  facts.version = request.version();
  facts.host = View(request[http::field::host]);
  facts.origin = View(request[http::field::origin]);
  facts.websocket_upgrade = beast::websocket::is_upgrade(request);
  facts.export_header = request.find("X-Dream-Export") != request.end();
  const RequestFilter::Decision decision = shared_.filter.Decide(facts);
  using Action = RequestFilter::Decision::Action;
  switch (decision.action) {
    case Action::kRefuse:
      Refuse(decision.status, decision.reason);
      return;
    case Action::kWebSocket:
      if (shared_.client_count.load() >= ViewServer::kMaxClients) {
        Refuse(503, "already " + std::to_string(ViewServer::kMaxClients) + " browsers connected");
        return;
      }
      std::make_shared<WebSocketSession>(stream_.release_socket(), shared_)->Accept(parser_->release());
      return;
    case Action::kRunData:
      if (shared_.run_data == nullptr) {
        Refuse(404, "the run is not loaded yet");
        return;
      }
      Send("application/json", *shared_.run_data, 200, request.keep_alive(), shared_.run_data);
      return;
    case Action::kExportStart:
    case Action::kExportStatus:
    case Action::kExportVideo:
      ServeExport(decision, request.keep_alive());
      return;
    case Action::kAsset:
      if (const ViewAsset* asset = FindViewAsset(decision.asset)) {
        Send(asset->content_type, asset->body, 200, request.keep_alive(), nullptr);
      } else {
        Refuse(404, "not found");
      }
      return;
  }
}

void HttpSession::ServeExport(const RequestFilter::Decision& decision, bool keep_alive) {
  using Action = RequestFilter::Decision::Action;
  VideoExports* exports = shared_.exports.get();
  if (exports == nullptr) {
    Refuse(409,
           "this view is live: a video is exported from a finished run's replay (dream run --view turns into it at "
           "the run's end; or dream view RUN), or with dream render RUN --out FILE.mp4");
    return;
  }
  if (decision.action == Action::kExportStart) {
    const VideoExports::Answer answer = exports->Start(decision.query);
    auto body = std::make_shared<const std::string>(answer.json);
    Send("application/json", *body, answer.status, keep_alive, body);
  } else if (decision.action == Action::kExportStatus) {
    auto body = std::make_shared<const std::string>(exports->StatusJson());
    Send("application/json", *body, 200, keep_alive, body);
  } else {
    const VideoExports::Video video = exports->Finished();
    if (!video.bytes) {
      Refuse(404, "no exported video yet (start one: the page's Export video)");
      return;
    }
    const bool gif = video.file_name.size() > 4 && video.file_name.substr(video.file_name.size() - 4) == ".gif";
    Send(gif ? "image/gif" : "video/mp4", *video.bytes, 200, keep_alive, video.bytes, video.file_name);
  }
}

void HttpSession::Refuse(int status, const std::string& reason) {
  spdlog::debug("dream view: refused a request ({}): {}", status, reason);
  auto text = std::make_shared<const std::string>(std::to_string(status) + " " + reason + "\n");
  Send("text/plain; charset=utf-8", *text, status, false, text);
}

void HttpSession::Send(std::string_view content_type, std::string_view body, int status, bool keep_alive,
                       std::shared_ptr<const std::string> owner, const std::string& download_name) {
  body_owner_ = std::move(owner);
  response_ = std::make_shared<Response>(static_cast<http::status>(status), 11);
  response_->set(http::field::server, "dream view");
  response_->set(http::field::content_type, beast::string_view(content_type.data(), content_type.size()));
  response_->set(http::field::cache_control, "no-store");
  response_->set("X-Content-Type-Options", "nosniff");
  // The page loads nothing but its own files, and talks only to this server.
  response_->set("Content-Security-Policy", "default-src 'self'; connect-src 'self'; img-src 'self' data:");
  response_->body() = http::span_body<const char>::value_type(body.data(), body.size());
  // A name of safe characters only (VideoExports::FileName): nothing to escape.
  if (!download_name.empty())
    response_->set(http::field::content_disposition, "attachment; filename=\"" + download_name + "\"");
  response_->keep_alive(keep_alive);
  response_->prepare_payload();
  stream_.expires_after(kRequestTimeout * 4);  // a large /run.json to a slow reader
  http::async_write(stream_, *response_, [self = shared_from_this(), keep_alive](beast::error_code error, size_t) {
    self->response_.reset();
    self->body_owner_.reset();
    if (error || !keep_alive) {
      self->Close();
    } else {
      self->Read();
    }
  });
}

void HttpSession::Close() {
  beast::error_code ignored;
  stream_.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_send, ignored);
  stream_.close();
}

}  // namespace dream::view
