#include "dream/view/request_filter.h"

#include <gtest/gtest.h>

#include <string>

namespace dream::view {
namespace {

using Action = RequestFilter::Decision::Action;

RequestFilter::Request Get(std::string_view target, std::string_view host = "127.0.0.1:8077") {
  RequestFilter::Request request;
  request.method = "GET";
  request.target = target;
  request.host = host;
  return request;
}

TEST(RequestFilterTest, ServesThePagesOwnAssets) {
  const RequestFilter filter(true, 8077, false);
  for (const auto& [target, asset] : {std::pair{"/", "index.html"},
                                      {"/index.html", "index.html"},
                                      {"/view.js", "view.js"},
                                      {"/arena.js", "arena.js"},
                                      {"/view.css", "view.css"},
                                      {"/view.js?v=2", "view.js"}}) {
    const auto decision = filter.Decide(Get(target));
    EXPECT_EQ(decision.action, Action::kAsset) << target << ": " << decision.reason;
    EXPECT_EQ(decision.asset, asset) << target;
  }
}

TEST(RequestFilterTest, ExportsStartOnlyWithThePagesHeaderAndKeepTheirQuery) {
  const RequestFilter filter(true, 8077, true);
  auto start = Get("/export/start?format=gif&x0=-1.5&from=3");
  EXPECT_EQ(filter.Decide(start).action, Action::kRefuse);
  EXPECT_EQ(filter.Decide(start).status, 403);
  start.export_header = true;
  const auto decision = filter.Decide(start);
  EXPECT_EQ(decision.action, Action::kExportStart);
  EXPECT_EQ(decision.query, "format=gif&x0=-1.5&from=3");
  EXPECT_EQ(filter.Decide(Get("/export/status")).action, Action::kExportStatus);
  EXPECT_EQ(filter.Decide(Get("/export/video?job=2")).action, Action::kExportVideo);
  EXPECT_EQ(filter.Decide(Get("/export.js")).asset, "export.js");
  // The filter's character rules hold for the query: no escapes, no quotes.
  auto escaped = Get("/export/start?x0=%2d1");
  escaped.export_header = true;
  EXPECT_EQ(filter.Decide(escaped).status, 400);
}

TEST(RequestFilterTest, RefusesTraversalAndFileSystemPaths) {
  const RequestFilter filter(true, 8077, false);
  for (const char* target : {"/../etc/passwd", "/a/../view.js", "/..", "//etc/passwd", "/%2e%2e/etc/passwd",
                             "/view.js%00", "/..\\..\\windows", "/etc/passwd", "/assets/view.js", "/./view.js"}) {
    const auto decision = filter.Decide(Get(target));
    EXPECT_EQ(decision.action, Action::kRefuse) << target;
    EXPECT_GE(decision.status, 400) << target;
    EXPECT_LT(decision.status, 500) << target;
  }
  EXPECT_EQ(filter.Decide(Get("/../etc/passwd")).status, 400);
  EXPECT_EQ(filter.Decide(Get("/etc/passwd")).status, 404);  // a plain unknown name: not found, nothing read
}

TEST(RequestFilterTest, RefusesMalformedRequests) {
  const RequestFilter filter(true, 8077, false);
  auto request = Get("/");
  request.method = "POST";
  EXPECT_EQ(filter.Decide(request).status, 405);
  request = Get("http://127.0.0.1:8077/");  // absolute form: not a path
  EXPECT_EQ(filter.Decide(request).status, 400);
  request = Get("");
  EXPECT_EQ(filter.Decide(request).status, 400);
  request = Get("/");
  request.version = 20;
  EXPECT_EQ(filter.Decide(request).status, 400);
  request = Get("/", "");
  EXPECT_EQ(filter.Decide(request).status, 400);  // no Host
  request = Get("/?a=<script>");
  EXPECT_EQ(filter.Decide(request).status, 400);
}

TEST(RequestFilterTest, RefusesOversizedTargets) {
  const RequestFilter filter(true, 8077, false);
  const std::string longest = "/" + std::string(RequestFilter::kMaxTargetChars - 1, 'a');
  EXPECT_EQ(filter.Decide(Get(longest)).status, 404);  // at the limit: judged (unknown name)
  const std::string over = "/" + std::string(RequestFilter::kMaxTargetChars, 'a');
  const auto decision = filter.Decide(Get(over));
  EXPECT_EQ(decision.status, 414);
  EXPECT_NE(decision.reason.find("256"), std::string::npos) << decision.reason;
}

TEST(RequestFilterTest, OnLoopbackOnlyLoopbackHostsAreAnswered) {
  const RequestFilter filter(true, 8077, false);
  for (const char* host : {"127.0.0.1:8077", "localhost:8077", "[::1]:8077"}) {
    EXPECT_EQ(filter.Decide(Get("/", host)).action, Action::kAsset) << host;
  }
  for (const char* host : {"evil.example:8077", "127.0.0.1:9999", "localhost", "127.0.0.1.evil.example:8077"}) {
    EXPECT_EQ(filter.Decide(Get("/", host)).status, 403) << host;  // DNS rebinding: another name for this server
  }
  const RequestFilter exposed(false, 8077, false);  // --bind 0.0.0.0: on purpose, any name
  EXPECT_EQ(exposed.Decide(Get("/", "robots-lab:8077")).action, Action::kAsset);
}

TEST(RequestFilterTest, WebSocketOnlyOnItsPathWithAnUpgradeFromThisOrigin) {
  const RequestFilter filter(true, 8077, false);
  auto request = Get("/ws");
  EXPECT_EQ(filter.Decide(request).status, 426);  // a plain GET of the socket's path
  request.websocket_upgrade = true;
  EXPECT_EQ(filter.Decide(request).action, Action::kWebSocket);
  request.origin = "http://127.0.0.1:8077";
  EXPECT_EQ(filter.Decide(request).action, Action::kWebSocket);
  request.origin = "http://evil.example";
  EXPECT_EQ(filter.Decide(request).status, 403);  // another site's page may not read the run
  request = Get("/view.js");
  request.websocket_upgrade = true;
  EXPECT_EQ(filter.Decide(request).status, 400);
}

TEST(RequestFilterTest, RunDataOnlyInReplay) {
  EXPECT_EQ(RequestFilter(true, 8077, false).Decide(Get("/run.json")).status, 404);
  EXPECT_EQ(RequestFilter(true, 8077, true).Decide(Get("/run.json")).action, Action::kRunData);
}

}  // namespace
}  // namespace dream::view
