#include "websocket_session.h"

#include <utility>

#include "dream/view/view_server.h"

namespace dream::view {

namespace beast = boost::beast;
namespace websocket = beast::websocket;

WebSocketSession::WebSocketSession(boost::asio::ip::tcp::socket socket, ServerShared& shared)
    : ws_(std::move(socket)), shared_(shared), queue_(shared.queue_frames) {}

WebSocketSession::~WebSocketSession() {
  if (counted_) shared_.client_count.fetch_sub(1);
}

void WebSocketSession::Accept(beast::http::request<beast::http::empty_body> request) {
  beast::get_lowest_layer(ws_).expires_never();  // the websocket's own timeouts take over
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& response) { response.set(beast::http::field::server, "dream view"); }));
  ws_.read_message_max(ViewServer::kMaxClientMessageBytes);
  ws_.text(true);
  shared_.client_count.fetch_add(1);
  counted_ = true;
  ws_.async_accept(request, [self = shared_from_this()](beast::error_code error) {
    if (error) return;  // the session ends with the last handler holding it
    self->open_ = true;
    self->shared_.clients.push_back(self);
    if (self->shared_.setup) self->Send(self->shared_.setup);
    if (self->shared_.latest_frame) self->Send(self->shared_.latest_frame);
    self->Read();
  });
}

void WebSocketSession::Read() {
  ws_.async_read(read_buffer_, [self = shared_from_this()](beast::error_code error, size_t) {
    if (error) {  // closed, timed out, or a message over the limit (the stream has closed it)
      self->Stop();
      return;
    }
    if (self->ws_.got_text()) self->shared_.HandClientMessage(beast::buffers_to_string(self->read_buffer_.data()));
    self->read_buffer_.consume(self->read_buffer_.size());
    self->Read();
  });
}

void WebSocketSession::Send(ClientQueue::Message message) {
  if (!open_ || message == nullptr) return;
  const int64_t dropped_before = queue_.dropped();
  queue_.Push(std::move(message));
  shared_.dropped_frames.fetch_add(queue_.dropped() - dropped_before);
  if (writing_ == nullptr) WriteNext();
}

void WebSocketSession::WriteNext() {
  writing_ = queue_.Pop();
  if (writing_ == nullptr) return;
  shared_.writes_in_flight.fetch_add(1);
  ws_.async_write(boost::asio::buffer(*writing_), [self = shared_from_this()](beast::error_code error, size_t) {
    self->writing_.reset();
    if (error) {
      self->Stop();
    } else {
      self->WriteNext();
    }
    self->shared_.writes_in_flight.fetch_sub(1);  // after the next write started: never 0 between two
  });
}

void WebSocketSession::Stop() {
  open_ = false;
  while (queue_.Pop() != nullptr) {
  }
}

}  // namespace dream::view
