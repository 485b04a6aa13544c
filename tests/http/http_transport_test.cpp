// Every route through the real transport (in-process server, httplib::Client), checked against the
// OpenAPI document, plus the per-request log, the metrics it feeds, keep-alive latency and shutdown.
#include "http/http_transport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <mutex>

#include "openapi_conformance.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::conformance_error;
using softtune::http::testing::quick_options;
using softtune::http::testing::TestServer;

namespace {

using softtune::http::testing::kJson;

using softtune::http::testing::media_type;

// GET `path`, expecting 200 with a JSON body; the body.
std::string get_json(const TestServer& s, const char* path) {
  auto r = s.client().Get(path);
  if (!r) return "(no response)";
  EXPECT_EQ(r->status, 200) << path;
  EXPECT_EQ(media_type(r), kJson) << path;
  return r->body;
}

}  // namespace

TEST(HttpRoutes, HealthConforms) {
  TestServer s;
  EXPECT_EQ(conformance_error("/api/v1/health", "get", 200, kJson, json::parse(get_json(s, "/api/v1/health"))), "");
}

TEST(HttpRoutes, TuneAnswersTheCliContractAndConforms) {
  TestServer s;
  // 10 Hz free at 60 fps, exact mode: the discrete poles sit on the continuous ones, so the achieved
  // frequency is the asked one (the standard mapping would give ~7.7 Hz, docs/math.md).
  auto r = s.client().Post("/api/v1/tune", R"({"frequency_hz": 10, "damping_ratio": 0.2, "effective_mass": 1,
                                               "fps": 60, "mode": "exact"})", kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  EXPECT_NEAR(doc["achieved"]["frequency_hz"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(doc["achieved"]["damping_ratio"].get<double>(), 0.2, 1e-9);
  EXPECT_EQ(conformance_error("/api/v1/tune", "post", 200, kJson, doc), "");
}

TEST(HttpRoutes, TuneClampsComeBackAsWarnings) {
  TestServer s;
  // 40 Hz at 60 fps is above Nyquist (30 Hz): exact mode clamps and says so in warnings.
  auto r = s.client().Post("/api/v1/tune", R"({"frequency_hz": 40, "oscillation": "free", "effective_mass": 1,
                                               "fps": 60, "mode": "exact"})", kJson);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json doc = json::parse(r->body);
  bool clamped = false;
  for (const json& w : doc["warnings"]) clamped = clamped || w["code"] == "nyquist_clamped";
  EXPECT_TRUE(clamped) << doc["warnings"].dump();
  EXPECT_LE(doc["frequency_hz"].get<double>(), 30.0 + 1e-9);
  EXPECT_EQ(conformance_error("/api/v1/tune", "post", 200, kJson, doc), "");
}

TEST(HttpRoutes, ValueOutOfRangeIs422NamingTheField) {
  TestServer s;
  auto r = s.client().Post("/api/v1/tune", R"({"response_frames": 12, "oscillation": "some",
      "constraint": {"dimension": 2, "type": "linear", "body_a": {"mass": -3}, "body_b": "static",
                     "anchor_a": [0, 0], "anchor_b": [0, 0], "axis": [1, 0]}})", kJson);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_EQ(media_type(r), "application/problem+json");
  const json p = json::parse(r->body);
  EXPECT_EQ(p["field"], "constraint.body_a.mass");
  EXPECT_NE(p["detail"].get<std::string>().find("kg"), std::string::npos);
  EXPECT_EQ(conformance_error("/api/v1/tune", "post", 422, "application/problem+json", p), "");
}

TEST(HttpRoutes, MalformedJsonIs400) {
  TestServer s;
  for (const char* body : {R"({"fps": 60,)", "", R"({"fps": 60, "fps": 60})", "[1, 2"}) {
    auto r = s.client().Post("/api/v1/tune", body, kJson);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << body;
    EXPECT_EQ(conformance_error("/api/v1/tune", "post", 400, "application/problem+json", json::parse(r->body)), "");
  }
}

TEST(HttpRoutes, UnknownRoutesAndWrongMethods) {
  TestServer s;
  auto missing = s.client().Get("/api/v1/nothing");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(json::parse(missing->body)["field"], "path");
  auto wrong = s.client().Get("/api/v1/tune");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 405);
  EXPECT_EQ(wrong->get_header_value("Allow"), "POST, OPTIONS");
  auto post_unknown = s.client().Post("/api/v1/nothing", "{}", kJson);
  ASSERT_TRUE(post_unknown);
  EXPECT_EQ(post_unknown->status, 404);
}

TEST(HttpRoutes, OpenApiServesTheDocument) {
  TestServer s;
  EXPECT_EQ(get_json(s, "/api/v1/openapi.json"), softtune::http::openapi_text());
}

TEST(HttpRoutes, StaticPageWithContentTypes) {
  TestServer s;
  std::ifstream in(SOFTTUNE_SOURCE_DIR "/web/index.html", std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* path : {"/", "/index.html"}) {
    auto r = s.client().Get(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << path;
    EXPECT_EQ(r->get_header_value("Content-Type"), "text/html; charset=utf-8");
    EXPECT_EQ(r->body, file);
  }
  auto head = s.client().Head("/");
  ASSERT_TRUE(head);
  EXPECT_EQ(head->status, 200);
  EXPECT_TRUE(head->body.empty());
  auto missing = s.client().Get("/missing.js");
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);
  EXPECT_EQ(missing->get_header_value("Content-Type"), "application/problem+json");
}

TEST(HttpRoutes, MetricsCountRequestsByRouteAndStatus) {
  TestServer s;
  // One keep-alive connection: its worker records each request before it reads the next one.
  auto client = s.client();
  client.set_keep_alive(true);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(client.Get("/api/v1/health"));
  ASSERT_TRUE(client.Post("/api/v1/tune", R"({"fps": 60)", kJson));
  ASSERT_TRUE(client.Get("/no/such/file.txt"));
  s.service().metrics().record_cache("preview", true);
  auto r = client.Get("/metrics");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(media_type(r), "text/plain");
  const std::string& t = r->body;
  EXPECT_NE(t.find("softtune_requests_total{route=\"/api/v1/health\",status=\"200\"} 3\n"), std::string::npos) << t;
  EXPECT_NE(t.find("softtune_requests_total{route=\"/api/v1/tune\",status=\"400\"} 1\n"), std::string::npos) << t;
  EXPECT_NE(t.find("softtune_requests_total{route=\"/{path...}\",status=\"404\"} 1\n"), std::string::npos) << t;
  EXPECT_NE(t.find("softtune_request_duration_seconds_count{route=\"/api/v1/health\"} 3\n"), std::string::npos) << t;
  EXPECT_NE(t.find("softtune_cache_hits_total{cache=\"preview\"} 1\n"), std::string::npos) << t;
}

TEST(HttpTransport, LogsOneLinePerRequest) {
  std::mutex mutex;
  std::vector<std::string> lines;
  auto options = quick_options();
  options.log = [&](std::string_view line) {
    const std::lock_guard lock(mutex);
    lines.emplace_back(line);
  };
  {
    TestServer s(options);
    auto client = s.client();
    client.set_keep_alive(true);  // one connection: the lines come in request order
    ASSERT_TRUE(client.Get("/api/v1/health"));
    ASSERT_TRUE(client.Post("/api/v1/tune", "{}", "text/plain"));
  }
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("GET /api/v1/health 200 ", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("POST /api/v1/tune 415 ", 0), 0u) << lines[1];
  EXPECT_EQ(lines[0].substr(lines[0].size() - 2), "us");
}

TEST(HttpTransport, KeepAliveRequestsDoNotWaitForDelayedAcks) {
  // Without TCP_NODELAY the response body waits for the ACK of its headers, which the client delays
  // by ~40 ms: 20 requests would take >= 800 ms. With it they take a few ms.
  TestServer s;
  auto client = s.client();
  client.set_keep_alive(true);
  ASSERT_TRUE(client.Get("/api/v1/health"));
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 20; ++i) ASSERT_TRUE(client.Get("/api/v1/health"));
  const auto elapsed = std::chrono::steady_clock::now() - start;
  EXPECT_LT(elapsed, std::chrono::milliseconds(400));
}

TEST(HttpTransport, StopClosesIdleKeepAliveConnectionsPromptly) {
  auto options = quick_options();
  options.keep_alive_timeout = std::chrono::milliseconds(10'000);
  TestServer s(options);
  auto client = s.client();
  client.set_keep_alive(true);
  ASSERT_TRUE(client.Get("/api/v1/health"));  // the connection now idles in keep-alive
  const auto start = std::chrono::steady_clock::now();
  s.server().stop();
  // ~TestServer joins run(), which waits for the worker holding the idle connection.
  while (s.server().running()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  softtune::http::testing::RawConnection probe(s.port());
  EXPECT_FALSE(probe.connected());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(2000));
}
