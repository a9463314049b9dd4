#include "dream/view/view_server.h"

#include <spdlog/spdlog.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <chrono>
#include <future>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

#include "dream/view/thread_priority.h"
#include "http_session.h"
#include "server_shared.h"
#include "websocket_session.h"

namespace dream::view {

namespace net = boost::asio;
using tcp = net::ip::tcp;

class ViewServer::Impl {
 public:
  explicit Impl(const Options& options);
  ~Impl();

  void Accept();
  void Broadcast(std::shared_ptr<const std::string> frame);

  std::string bind_address_;
  int port_ = 0;
  // Declared in this order so the connections (owned by the io_context's
  // handlers) go before what they share.
  std::unique_ptr<ServerShared> shared_;
  net::io_context io_;
  tcp::acceptor acceptor_;
  std::thread thread_;
};

namespace {

tcp::endpoint EndpointOf(const std::string& address, int port) {
  boost::system::error_code error;
  const net::ip::address ip = net::ip::make_address(address, error);
  if (error) {
    throw std::runtime_error("--bind " + address + " is not an IP address (e.g. 127.0.0.1, 0.0.0.0, ::1)");
  }
  if (port < 0 || port > 65535) {
    throw std::runtime_error("--port " + std::to_string(port) + " is not a port (0 to 65535)");
  }
  return tcp::endpoint(ip, static_cast<unsigned short>(port));
}

}  // namespace

ViewServer::Impl::Impl(const Options& options) : bind_address_(options.bind_address), acceptor_(io_) {
  const tcp::endpoint endpoint = EndpointOf(options.bind_address, options.port);
  boost::system::error_code error;
  acceptor_.open(endpoint.protocol(), error);
  if (!error) acceptor_.set_option(net::socket_base::reuse_address(true), error);
  if (!error) acceptor_.bind(endpoint, error);
  if (!error) acceptor_.listen(net::socket_base::max_listen_connections, error);
  if (error) {
    throw std::runtime_error("the view's page cannot listen on " + options.bind_address + ":" +
                             std::to_string(options.port) + ": " + error.message() +
                             (error == net::error::address_in_use ? " (choose another with --port)" : ""));
  }
  port_ = acceptor_.local_endpoint().port();
  shared_ = std::make_unique<ServerShared>(RequestFilter(endpoint.address().is_loopback(), port_, options.replay),
                                           options.queue_frames);
  Accept();
  thread_ = std::thread([this] {
    LowerThisThreadsPriority();
    io_.run();
  });
}

ViewServer::Impl::~Impl() {
  // The last frame (a run's FINISHED) was just broadcast: let the browsers
  // that keep up receive it, for half a second at most, then stop.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
  auto flushed = std::make_shared<std::promise<void>>();
  std::future<void> posted = flushed->get_future();
  net::post(io_, [flushed] { flushed->set_value(); });
  if (posted.wait_until(deadline) == std::future_status::ready) {
    while (shared_->writes_in_flight.load() > 0 && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }
  io_.stop();
  if (thread_.joinable()) thread_.join();
}

void ViewServer::Impl::Accept() {
  acceptor_.async_accept([this](boost::system::error_code error, tcp::socket socket) {
    if (!error && shared_->http_connections.load() >= kMaxHttpConnections) {
      boost::system::error_code ignored;
      socket.close(ignored);  // a flood of connections: refused as they come, not held
    } else if (!error) {
      std::make_shared<HttpSession>(std::move(socket), *shared_)->Start();
    } else if (error == net::error::operation_aborted) {
      return;
    } else {
      spdlog::debug("dream view: accept failed: {}", error.message());  // out of descriptors, ...: try again
    }
    Accept();
  });
}

void ViewServer::Impl::Broadcast(std::shared_ptr<const std::string> frame) {
  shared_->latest_frame = frame;
  auto& clients = shared_->clients;
  size_t kept = 0;
  for (auto& weak : clients) {
    if (const std::shared_ptr<WebSocketSession> client = weak.lock()) {
      client->Send(frame);
      clients[kept++] = weak;
    }
  }
  clients.resize(kept);
}

ViewServer::ViewServer(const Options& options) {
  if (options.queue_frames == 0) throw std::invalid_argument("ViewServer: a browser's queue must hold a frame");
  impl_ = std::make_unique<Impl>(options);
}

ViewServer::~ViewServer() = default;

int ViewServer::port() const { return impl_->port_; }

std::string ViewServer::url() const {
  const bool v6 = impl_->bind_address_.find(':') != std::string::npos;
  // A wildcard address is not one a browser can open: name the loopback one.
  const std::string& bind = impl_->bind_address_;
  const std::string host = bind == "0.0.0.0" ? "127.0.0.1" : bind == "::" ? "::1" : bind;
  return "http://" + (v6 ? "[" + host + "]" : host) + ":" + std::to_string(impl_->port_) + "/";
}

void ViewServer::SetSetup(std::string setup_json) {
  auto setup = std::make_shared<const std::string>(std::move(setup_json));
  net::post(impl_->io_, [impl = impl_.get(), setup] { impl->shared_->setup = setup; });
}

void ViewServer::SetRunData(std::string run_json) {
  auto data = std::make_shared<const std::string>(std::move(run_json));
  net::post(impl_->io_, [impl = impl_.get(), data] { impl->shared_->run_data = data; });
}

void ViewServer::ServeReplay(std::string setup_json, std::string run_json) {
  auto setup = std::make_shared<const std::string>(std::move(setup_json));
  auto data = std::make_shared<const std::string>(std::move(run_json));
  net::post(impl_->io_, [impl = impl_.get(), setup, data] {
    ServerShared& shared = *impl->shared_;
    shared.run_data = data;
    shared.filter.ServeRunData();
    shared.setup = setup;
    shared.latest_frame = nullptr;  // a browser that connects now gets the replay's setup alone
    impl->Broadcast(setup);         // pages open now: the setup tells them to load /run.json
    shared.latest_frame = nullptr;
  });
}

void ViewServer::SetVideoExports(std::shared_ptr<VideoExports> exports) {
  net::post(impl_->io_, [impl = impl_.get(), exports = std::move(exports)] { impl->shared_->exports = exports; });
}

void ViewServer::SetClientMessageHandler(std::function<void(const std::string&)> handler) {
  std::lock_guard<std::mutex> lock(impl_->shared_->client_message_mutex);
  impl_->shared_->on_client_message = std::move(handler);
}

void ViewServer::Broadcast(std::string frame_json) {
  auto frame = std::make_shared<const std::string>(std::move(frame_json));
  net::post(impl_->io_, [impl = impl_.get(), frame] { impl->Broadcast(frame); });
}

size_t ViewServer::clients() const { return impl_->shared_->client_count.load(); }

int64_t ViewServer::dropped_frames() const { return impl_->shared_->dropped_frames.load(); }

}  // namespace dream::view
