#pragma once

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <memory>

#include "dream/view/client_queue.h"
#include "server_shared.h"

namespace dream::view {

/// One browser's WebSocket: it gets the setup, the latest frame, then each
/// frame sent while it keeps up; a frame arriving while its ClientQueue is
/// full drops the oldest waiting one. What the browser sends is read (at most
/// ViewServer::kMaxClientMessageBytes a message, else the connection is
/// closed) and its text handed to the server's client message handler (the
/// user's choice of the run to draw), if any.
class WebSocketSession : public std::enable_shared_from_this<WebSocketSession> {
 public:
  WebSocketSession(boost::asio::ip::tcp::socket socket, ServerShared& shared);
  ~WebSocketSession();
  /// Completes the handshake of `request` (an upgrade the filter allowed).
  void Accept(boost::beast::http::request<boost::beast::http::empty_body> request);
  /// Queues `message` for this browser; starts writing if idle. Server thread only.
  void Send(ClientQueue::Message message);

 private:
  void Read();
  void WriteNext();
  void Stop();

  boost::beast::websocket::stream<boost::beast::tcp_stream> ws_;
  boost::beast::flat_buffer read_buffer_;
  ServerShared& shared_;
  ClientQueue queue_;
  ClientQueue::Message writing_;
  bool open_ = false;
  bool counted_ = false;
};

}  // namespace dream::view
