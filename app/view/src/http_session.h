#pragma once

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <memory>
#include <optional>
#include <string>

#include "server_shared.h"

namespace dream::view {

/// One HTTP connection of the view's server: reads each request with bounded
/// headers and no body, decides with the RequestFilter, and serves an asset
/// or /run.json, hands the connection to a WebSocketSession, or refuses
/// (4xx, then the connection is closed).
class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket socket, ServerShared& shared);
  ~HttpSession();
  void Start() { Read(); }

 private:
  using Response = boost::beast::http::response<boost::beast::http::span_body<const char>>;
  void Read();
  void OnRead(boost::beast::error_code error);
  void Serve(const boost::beast::http::request<boost::beast::http::empty_body>& request);
  void ServeExport(const RequestFilter::Decision& decision, bool keep_alive);
  void Refuse(int status, const std::string& reason);
  /// `download_name`: sent as an attachment of that name (Content-Disposition).
  void Send(std::string_view content_type, std::string_view body, int status, bool keep_alive,
            std::shared_ptr<const std::string> owner, const std::string& download_name = "");
  void Close();

  boost::beast::tcp_stream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<boost::beast::http::request_parser<boost::beast::http::empty_body>> parser_;
  ServerShared& shared_;
  // What the response being written points into (refusals' text, /run.json).
  std::shared_ptr<const std::string> body_owner_;
  std::shared_ptr<Response> response_;
};

}  // namespace dream::view
