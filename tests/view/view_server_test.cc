#include "dream/view/view_server.h"

#include "dream/view/video_exports.h"

#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>
#include <chrono>
#include <fstream>
#include <future>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace dream::view {
namespace {

namespace net = boost::asio;
namespace websocket = boost::beast::websocket;
using tcp = net::ip::tcp;

ViewServer::Options AnyPort(bool replay = false) { return {"127.0.0.1", 0, replay, 4}; }

/// Sends `request` as it is and reads until the server closes the connection
/// (every refusal closes it; the good requests here ask it to).
std::string Exchange(int port, const std::string& request) {
  net::io_context io;
  tcp::socket socket(io);
  socket.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(port)));
  net::write(socket, net::buffer(request));
  std::string response;
  boost::system::error_code error;
  char chunk[4096];
  while (!error) {
    const size_t n = socket.read_some(net::buffer(chunk), error);
    response.append(chunk, n);
  }
  EXPECT_TRUE(error == net::error::eof || error == net::error::connection_reset) << error.message();
  return response;
}

std::string Get(int port, const std::string& target) {
  return "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\nConnection: close\r\n\r\n";
}

std::string StatusLine(const std::string& response) { return response.substr(0, response.find("\r\n")); }

TEST(ViewServerTest, ServesThePageAndItsScripts) {
  ViewServer server(AnyPort());
  const std::string page = Exchange(server.port(), Get(server.port(), "/"));
  EXPECT_EQ(StatusLine(page), "HTTP/1.1 200 OK");
  EXPECT_NE(page.find("Content-Type: text/html"), std::string::npos);
  EXPECT_NE(page.find("<canvas id=\"arena\""), std::string::npos);
  EXPECT_NE(page.find("Content-Security-Policy: default-src 'self'"), std::string::npos);
  for (const char* script : {"/view.js", "/arena.js"}) {
    const std::string js = Exchange(server.port(), Get(server.port(), script));
    EXPECT_EQ(StatusLine(js), "HTTP/1.1 200 OK") << script;
    EXPECT_NE(js.find("text/javascript"), std::string::npos) << script;
  }
  EXPECT_EQ(server.url(), "http://127.0.0.1:" + std::to_string(server.port()) + "/");
}

TEST(ViewServerTest, RefusesTraversalMalformedAndOversizedRequestsAndCloses) {
  ViewServer server(AnyPort());
  const int port = server.port();
  const std::string host = "Host: 127.0.0.1:" + std::to_string(port) + "\r\n";
  struct Case {
    std::string request;
    std::string status;
  };
  const Case cases[] = {
      {Get(port, "/../../etc/passwd"), "HTTP/1.1 400 Bad Request"},
      {Get(port, "/%2e%2e/etc/passwd"), "HTTP/1.1 400 Bad Request"},
      {Get(port, "/etc/passwd"), "HTTP/1.1 404 Not Found"},
      {"GARBAGE\r\n\r\n", "HTTP/1.1 400 Bad Request"},
      {"GET / HTTP/1.1\r\n" + host + "Content-Length: 5\r\n\r\nhello", "HTTP/1.1 400 Bad Request"},  // no bodies
      {"POST / HTTP/1.1\r\n" + host + "\r\n", "HTTP/1.1 405 Method Not Allowed"},
      {"GET / HTTP/1.1\r\nHost: evil.example\r\n\r\n", "HTTP/1.1 403 Forbidden"},
      {"GET /" + std::string(300, 'a') + " HTTP/1.1\r\n" + host + "\r\n", "HTTP/1.1 414 URI Too Long"},
      {"GET / HTTP/1.1\r\n" + host + "X-Big: " + std::string(ViewServer::kMaxHeaderBytes, 'x') + "\r\n\r\n",
       "HTTP/1.1 431 Request Header Fields Too Large"},
      {"GET /" + std::string(ViewServer::kMaxHeaderBytes * 2, 'a') + " HTTP/1.1\r\n\r\n",
       "HTTP/1.1 431 Request Header Fields Too Large"},
      {Get(port, "/ws"), "HTTP/1.1 426 Upgrade Required"},
      {Get(port, "/run.json"), "HTTP/1.1 404 Not Found"},  // live: no run to replay
  };
  for (const Case& c : cases) {
    // Exchange() returns only once the server closed the connection.
    EXPECT_EQ(StatusLine(Exchange(port, c.request)), c.status) << c.request.substr(0, 60);
  }
}

TEST(ViewServerTest, ServesTheReplayedRun) {
  ViewServer server(AnyPort(true));
  server.SetRunData("{\"type\":\"run\"}");
  const std::string response = Exchange(server.port(), Get(server.port(), "/run.json"));
  EXPECT_EQ(StatusLine(response), "HTTP/1.1 200 OK");
  EXPECT_EQ(response.substr(response.size() - 14), "{\"type\":\"run\"}");
}

TEST(ViewServerTest, ExportsAreRefusedLiveAndServedInAReplay) {
  ViewServer server(AnyPort(true));
  auto get = [&](const std::string& target, const std::string& headers = "") {
    return Exchange(server.port(), "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(server.port()) +
                                       "\r\n" + headers + "Connection: close\r\n\r\n");
  };
  // Live (no exports set): said so, with where a video comes from.
  const std::string live = get("/export/start", "X-Dream-Export: 1\r\n");
  EXPECT_EQ(StatusLine(live), "HTTP/1.1 409 Conflict");
  EXPECT_NE(live.find("this view is live"), std::string::npos) << live;
  VideoExports::Run run;
  run.name = "demo";
  run.render_command = "dream render demo";
  run.last_step = 100;
  server.SetVideoExports(std::make_shared<VideoExports>(
      run, [](const VideoExportRequest&, const std::string& out, const std::function<void(int, int)>&,
              const std::atomic<bool>&) { std::ofstream(out) << "frames"; }));
  // Without the page's header: refused (another site's page cannot send it).
  EXPECT_EQ(StatusLine(get("/export/start")), "HTTP/1.1 403 Forbidden");
  EXPECT_EQ(StatusLine(get("/export/start?fps=500", "X-Dream-Export: 1\r\n")), "HTTP/1.1 400 Bad Request");
  EXPECT_EQ(StatusLine(get("/export/video")), "HTTP/1.1 404 Not Found");
  EXPECT_EQ(StatusLine(get("/export/start?format=gif&to=20&from=10", "X-Dream-Export: 1\r\n")),
            "HTTP/1.1 202 Accepted");
  std::string status;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (status.find("\"state\":\"done\"") == std::string::npos && std::chrono::steady_clock::now() < deadline) {
    status = get("/export/status");
  }
  EXPECT_NE(status.find("\"file\":\"demo_steps_10-20.gif\""), std::string::npos) << status;
  const std::string video = get("/export/video");
  EXPECT_EQ(StatusLine(video), "HTTP/1.1 200 OK");
  EXPECT_NE(video.find("Content-Type: image/gif"), std::string::npos);
  EXPECT_NE(video.find("Content-Disposition: attachment; filename=\"demo_steps_10-20.gif\""), std::string::npos);
  EXPECT_EQ(video.substr(video.size() - 6), "frames");
}

class Browser {
 public:
  explicit Browser(int port) : ws_(io_) {
    net::connect(ws_.next_layer(), tcp::resolver(io_).resolve("127.0.0.1", std::to_string(port)));
    ws_.handshake("127.0.0.1:" + std::to_string(port), "/ws");
  }
  std::string Read() {
    boost::beast::flat_buffer buffer;
    ws_.read(buffer);
    return boost::beast::buffers_to_string(buffer.data());
  }
  websocket::stream<tcp::socket>& ws() { return ws_; }

 private:
  net::io_context io_;
  websocket::stream<tcp::socket> ws_;
};

TEST(ViewServerTest, EachBrowserGetsTheSetupThenTheFrames) {
  ViewServer server(AnyPort());
  server.SetSetup("{\"type\":\"setup\"}");
  Browser first(server.port());
  Browser second(server.port());
  EXPECT_EQ(first.Read(), "{\"type\":\"setup\"}");
  EXPECT_EQ(second.Read(), "{\"type\":\"setup\"}");
  server.Broadcast("frame 1");
  EXPECT_EQ(first.Read(), "frame 1");
  EXPECT_EQ(second.Read(), "frame 1");
  Browser late(server.port());  // gets the setup and the latest frame at once
  EXPECT_EQ(late.Read(), "{\"type\":\"setup\"}");
  EXPECT_EQ(late.Read(), "frame 1");
  EXPECT_EQ(server.clients(), 3u);
}

// dream run --view at the run's end (issue 37 item 1): the live server serves
// the finished run at the same port; a page open gets the replay's setup, a
// page that connects later the replay's setup and no live frame.
TEST(ViewServerTest, ALiveServerBecomesTheReplayOfItsRun) {
  ViewServer server(AnyPort());
  server.SetSetup("{\"type\":\"setup\",\"mode\":\"live\"}");
  Browser open(server.port());
  EXPECT_EQ(open.Read(), "{\"type\":\"setup\",\"mode\":\"live\"}");
  server.Broadcast("last live frame");
  EXPECT_EQ(open.Read(), "last live frame");
  EXPECT_EQ(StatusLine(Exchange(server.port(), Get(server.port(), "/run.json"))), "HTTP/1.1 404 Not Found");

  server.ServeReplay("{\"type\":\"setup\",\"mode\":\"replay\"}", "{\"type\":\"run\"}");
  EXPECT_EQ(open.Read(), "{\"type\":\"setup\",\"mode\":\"replay\"}");
  const std::string response = Exchange(server.port(), Get(server.port(), "/run.json"));
  EXPECT_EQ(StatusLine(response), "HTTP/1.1 200 OK");
  EXPECT_EQ(response.substr(response.size() - 14), "{\"type\":\"run\"}");
  Browser late(server.port());
  EXPECT_EQ(late.Read(), "{\"type\":\"setup\",\"mode\":\"replay\"}");
  // Nothing follows the setup: a frame sent now would be the next message.
  server.Broadcast("marker");
  EXPECT_EQ(late.Read(), "marker");
}

TEST(ViewServerTest, AnOversizedMessageFromABrowserClosesItsSocket) {
  ViewServer server(AnyPort());
  server.SetSetup("setup");
  Browser browser(server.port());
  EXPECT_EQ(browser.Read(), "setup");
  browser.ws().write(net::buffer(std::string(ViewServer::kMaxClientMessageBytes + 1, 'x')));
  boost::beast::flat_buffer buffer;
  boost::system::error_code error;
  browser.ws().read(buffer, error);
  EXPECT_TRUE(error) << "the server kept a socket that sent " << ViewServer::kMaxClientMessageBytes + 1 << " bytes";
}

TEST(ViewServerTest, ABrowsersTextMessageReachesTheHandler) {
  ViewServer server(AnyPort());
  server.SetSetup("setup");
  std::promise<std::string> heard;
  server.SetClientMessageHandler([&heard](const std::string& message) { heard.set_value(message); });
  Browser browser(server.port());
  EXPECT_EQ(browser.Read(), "setup");
  browser.ws().text(true);
  browser.ws().write(net::buffer(std::string("follow 9")));
  std::future<std::string> message = heard.get_future();
  ASSERT_EQ(message.wait_for(std::chrono::seconds(60)), std::future_status::ready);  // a bound, not a margin
  EXPECT_EQ(message.get(), "follow 9");
  server.SetClientMessageHandler(nullptr);  // before `heard` is gone
}

TEST(ViewServerTest, ASlowBrowserLosesFramesAndOthersStillGetThem) {
  ViewServer server(AnyPort());
  server.SetSetup("setup");
  Browser slow(server.port());  // never reads after this
  EXPECT_EQ(slow.Read(), "setup");
  const std::string big(256 * 1024, 'f');
  // Enough to fill the kernel's socket buffers and the browser's queue of 4.
  for (int i = 0; i < 400 && server.dropped_frames() == 0; ++i) {
    server.Broadcast(big);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // let the server's thread write
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (server.dropped_frames() == 0 && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_GT(server.dropped_frames(), 0);
  Browser fresh(server.port());
  EXPECT_EQ(fresh.Read(), "setup");
  EXPECT_EQ(fresh.Read(), big);  // the latest frame
  server.Broadcast("after");
  EXPECT_EQ(fresh.Read(), "after");
}

TEST(ViewServerTest, AFloodOfConnectionsIsRefusedPastTheLimit) {
  ViewServer server(AnyPort());
  net::io_context io;
  const tcp::endpoint endpoint(net::ip::make_address("127.0.0.1"), static_cast<unsigned short>(server.port()));
  std::vector<tcp::socket> idle;  // connected, sending nothing
  for (size_t i = 0; i < ViewServer::kMaxHttpConnections; ++i) idle.emplace_back(io).connect(endpoint);
  // Accepted in order on the server's one thread: the next one finds the limit reached and is closed.
  tcp::socket extra(io);
  extra.connect(endpoint);
  char byte = 0;
  boost::system::error_code error;
  extra.read_some(net::buffer(&byte, 1), error);
  EXPECT_TRUE(error == net::error::eof || error == net::error::connection_reset) << error.message();
  idle.clear();  // once they go, the server answers again
  std::string response;
  for (int attempt = 0; attempt < 200 && StatusLine(response) != "HTTP/1.1 200 OK"; ++attempt) {
    response = Exchange(server.port(), Get(server.port(), "/view.css"));
  }
  EXPECT_EQ(StatusLine(response), "HTTP/1.1 200 OK");
}

TEST(ViewServerTest, APortInUseIsAClearError) {
  ViewServer first(AnyPort());
  try {
    ViewServer second({"127.0.0.1", first.port(), false, 4});
    FAIL() << "two servers listened on one port";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(std::to_string(first.port())), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("--port"), std::string::npos) << error.what();
  }
  EXPECT_THROW(ViewServer({"not-an-address", 0, false, 4}), std::runtime_error);
}

}  // namespace
}  // namespace dream::view
