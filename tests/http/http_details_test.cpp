// Issue 29's attacks and HTTP details against a live in-process server: a Range header is ignored (a
// thousand ranges made a 229 MB answer), a body trickling in holds no worker and ends in 408, probes have
// their own lane, and the RFC 9110/9112 details (Host, header names, 204/304 without Content-Length,
// static validators, OPTIONS and 405 with one Allow list, repeated query parameters, CORS on a 414).
#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "http/limits.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::body_of;
using softtune::http::testing::quick_options;
using softtune::http::testing::RawConnection;
using softtune::http::testing::status_of;
using softtune::http::testing::TestServer;
namespace limits = softtune::http::limits;
using namespace std::chrono_literals;

// Named, not anonymous: the test sources are compiled together (unity builds), beside other helpers.
namespace http_details_test {

const std::string kTune = R"({"response_frames": 12, "oscillation": "some", "effective_mass": 2})";

std::string exchange(int port, const std::string& request) { return softtune::http::testing::exchange(port, request, 2000ms); }

std::string head_of(const std::string& response) { return response.substr(0, response.find("\r\n\r\n") + 2); }

bool has_header(const std::string& response, const std::string& name) {
  return head_of(response).find("\r\n" + name + ":") != std::string::npos;
}

std::string get(const std::string& path, const std::string& headers = "") {
  return "GET " + path + " HTTP/1.1\r\nHost: t\r\nConnection: close\r\n" + headers + "\r\n";
}

std::string field_of(const std::string& response) {
  const json problem = json::parse(body_of(response), nullptr, false);
  return problem.is_object() ? problem.value("field", "?") : "?";
}


// RFC 9110 14.2 lets a server ignore Range: the answer is the whole representation, 200, however many
// ranges are asked for, and never larger than it.
TEST(HttpDetails, RangeIsIgnored) {
  TestServer s;
  const std::string whole = body_of(exchange(s.port(), get("/api/v1/openapi.json")));
  ASSERT_GT(whole.size(), 100000u);
  std::string ranges = "bytes=0-";
  for (int i = 1; i < 1000; ++i) ranges += ",0-";
  ASSERT_GT(ranges.size(), 2900u);
  for (const std::string& range : {ranges, std::string("bytes=0-9"), std::string("bytes=-5"), std::string("bytes=5-")}) {
    SCOPED_TRACE(range.substr(0, 40));
    const std::string r = exchange(s.port(), get("/api/v1/openapi.json", "Range: " + range + "\r\n"));
    EXPECT_EQ(status_of(r), 200);
    EXPECT_EQ(body_of(r), whole);
    EXPECT_FALSE(has_header(r, "Content-Range"));
  }
  const std::string head = exchange(s.port(), "HEAD /api/v1/health HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n");
  EXPECT_NE(head_of(head).find("\r\nAccept-Ranges: none\r\n"), std::string::npos) << head;
  // A Range header that is no byte-range list is refused by the library's parser, as a problem.
  const std::string bad = exchange(s.port(), get("/api/v1/health", "Range: items=0-1\r\n"));
  EXPECT_EQ(status_of(bad), 416);
  EXPECT_LT(bad.size(), 2000u);
}

// A body at one byte per 100 ms: it waits in the gate, not in a worker (one worker serves others
// meanwhile), and gets 408 once its grace plus its length at the minimum rate has passed.
TEST(HttpDetails, ASlowBodyHoldsNoWorkerAndEndsIn408) {
  auto options = quick_options();
  options.threads = 1;
  options.request_read_timeout = 5000ms;
  TestServer s(options);
  std::vector<std::unique_ptr<RawConnection>> slow;
  for (int i = 0; i < 4; ++i) {
    slow.push_back(std::make_unique<RawConnection>(s.port()));
    slow.back()->send("POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nContent-Length: " +
                      std::to_string(kTune.size()) + "\r\n\r\n{");
  }
  const auto start = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(200ms);
  auto tune = s.client().Post("/api/v1/tune", kTune, "application/json");
  ASSERT_TRUE(tune);
  EXPECT_EQ(tune->status, 200);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 800ms) << "the slow bodies held the only worker";
  std::string answer;
  for (int i = 0; i < 30 && !slow[0]->closed(); ++i) {
    slow[0]->send("\"");
    answer += slow[0]->receive_some(100ms);
  }
  answer += slow[0]->receive(500ms);
  const auto took = std::chrono::steady_clock::now() - start;
  EXPECT_EQ(status_of(answer), 408) << answer;
  EXPECT_GE(took, limits::kBodyGrace);
  EXPECT_LT(took, limits::kBodyGrace + 1500ms);
}

// A body sent at once in pieces is served (the gate waits for all of it).
TEST(HttpDetails, ABodyInPiecesIsServed) {
  TestServer s;
  RawConnection c(s.port());
  c.send("POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nConnection: close\r\nContent-Length: " +
         std::to_string(kTune.size()) + "\r\n\r\n");
  std::this_thread::sleep_for(50ms);
  c.send(kTune.substr(0, 10));
  std::this_thread::sleep_for(50ms);
  c.send(kTune.substr(10));
  EXPECT_EQ(status_of(c.receive(2000ms)), 200);
}

// Probes go to the reserved lane: with every worker busy on long requests, health still answers.
TEST(HttpDetails, HealthAnswersWhileEveryWorkerIsBusy) {
  auto options = quick_options();
  options.threads = 1;
  TestServer s(options, softtune::http::testing::presets_config());
  std::thread busy([&] {
    auto c = s.client();
    c.set_read_timeout(60, 0);
    // The default stability sweep: about a second of work on the only worker.
    c.Get("/api/v1/stability");
  });
  std::this_thread::sleep_for(100ms);
  const auto start = std::chrono::steady_clock::now();
  const std::string r = exchange(s.port(), get("/api/v1/health"));
  const auto took = std::chrono::steady_clock::now() - start;
  busy.join();
  EXPECT_EQ(status_of(r), 200);
  EXPECT_LT(took, 300ms);
}

TEST(HttpDetails, HostMustBeGivenOnceAndWellFormed) {
  TestServer s;
  EXPECT_EQ(status_of(exchange(s.port(), "GET /api/v1/health HTTP/1.1\r\nConnection: close\r\n\r\n")), 400);
  const std::string two = exchange(s.port(), "GET /api/v1/health HTTP/1.1\r\nHost: a\r\nHost: b\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(status_of(two), 400);
  EXPECT_EQ(field_of(two), "Host");
  const std::string spaced = exchange(s.port(), "GET /api/v1/health HTTP/1.1\r\nHost : x\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(status_of(spaced), 400);
  EXPECT_EQ(field_of(spaced), "Host");
  EXPECT_EQ(status_of(exchange(s.port(), "GET /api/v1/health HTTP/1.1\r\nHost: a b\r\nConnection: close\r\n\r\n")), 400);
  EXPECT_EQ(status_of(exchange(s.port(), "GET /api/v1/health HTTP/1.1\r\nHost: [::1]:8080\r\nConnection: close\r\n\r\n")), 200);
  EXPECT_EQ(status_of(exchange(s.port(), "GET /api/v1/health HTTP/1.0\r\n\r\n")), 200);  // 1.0 may omit Host
}

// "Transfer-Encoding : chunked" must not be read as another header while Content-Length frames the body.
TEST(HttpDetails, AHeaderNameWithASpaceBeforeItsColonIsRefused) {
  TestServer s;
  const std::string r = exchange(s.port(), "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                           "Transfer-Encoding : chunked\r\nContent-Length: " +
                                               std::to_string(kTune.size()) + "\r\n\r\n" + kTune);
  EXPECT_EQ(status_of(r), 400) << r;
  EXPECT_EQ(field_of(r), "Transfer-Encoding");
}

// RFC 9110 8.6: no Content-Length on a 204 or a 304; static files carry validators and answer 304.
TEST(HttpDetails, NoContentLengthWithoutContentAndStaticValidators) {
  TestServer s;
  const std::string page = exchange(s.port(), get("/index.html"));
  ASSERT_EQ(status_of(page), 200);
  const std::string head = head_of(page);
  const std::size_t at = head.find("\r\nETag: ");
  ASSERT_NE(at, std::string::npos) << head;
  const std::string etag = head.substr(at + 8, head.find("\r\n", at + 2) - at - 8);
  EXPECT_TRUE(has_header(page, "Last-Modified"));
  EXPECT_NE(head.find(" GMT\r\n"), std::string::npos);
  const std::string again = exchange(s.port(), get("/index.html", "If-None-Match: " + etag + "\r\n"));
  EXPECT_EQ(status_of(again), 304);
  EXPECT_FALSE(has_header(again, "Content-Length")) << again;
  EXPECT_TRUE(body_of(again).empty());
  const std::string options = exchange(s.port(), "OPTIONS /api/v1/tune HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(status_of(options), 204);
  EXPECT_FALSE(has_header(options, "Content-Length")) << options;
}

// One Allow list per path, whoever asks: a 405, a plain OPTIONS and (with CORS on) a preflight.
TEST(HttpDetails, AllowIsTheSameFor405OptionsAndPreflight) {
  auto config = softtune::http::testing::web_config();
  config.cors.origins = {"*"};
  TestServer s(quick_options(), config);
  auto c = s.client();
  auto wrong = c.Get("/api/v1/tune");
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->status, 405);
  auto plain = c.Options("/api/v1/tune");
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->status, 204);
  auto preflight = c.Options("/api/v1/tune", httplib::Headers{{"Origin", "https://a.example"},
                                                               {"Access-Control-Request-Method", "POST"}});
  ASSERT_TRUE(preflight);
  EXPECT_EQ(wrong->get_header_value("Allow"), "POST, OPTIONS");
  EXPECT_EQ(plain->get_header_value("Allow"), "POST, OPTIONS");
  EXPECT_EQ(preflight->get_header_value("Allow"), "POST, OPTIONS");
  auto post_static = c.Post("/index.html", "{}", "application/json");
  ASSERT_TRUE(post_static);
  EXPECT_EQ(post_static->status, 405);
  EXPECT_EQ(post_static->get_header_value("Allow"), "GET, HEAD, OPTIONS");
  auto post_api = c.Post("/api/v1/nothing", "{}", "application/json");
  ASSERT_TRUE(post_api);
  EXPECT_EQ(post_api->status, 404);  // no resource under /api/ without a route
}

TEST(HttpDetails, ARepeatedQueryParameterIsRefusedEvenWithEqualValues) {
  TestServer s(quick_options(), softtune::http::testing::presets_config());
  auto c = s.client();
  auto same = c.Post("/api/v1/accuracy?format=json&format=json", kTune, "application/json");
  ASSERT_TRUE(same);
  EXPECT_EQ(same->status, 422);
  EXPECT_EQ(json::parse(same->body)["field"], "format");
  auto identify = c.Post("/api/v1/identify?fps=60&fps=30", "time_s,x\n0,1\n0.1,0.5\n", "text/csv");
  ASSERT_TRUE(identify);
  EXPECT_EQ(identify->status, 422);
  EXPECT_EQ(json::parse(identify->body)["field"], "fps");
}

TEST(HttpDetails, IdentifyNamesItsQueryParametersAsWritten) {
  TestServer s;
  auto r = s.client().Post("/api/v1/identify?fps=-60&frequency_hz=5&damping_ratio=0.5&effective_mass=2", "time_s,x\n0,1\n0.1,0.5\n0.2,0.2\n", "text/csv");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_EQ(json::parse(r->body)["field"], "fps") << r->body;
}

TEST(HttpDetails, StabilityRefusesANullBody) {
  TestServer s;
  auto r = s.client().Post("/api/v1/stability", "null", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 422);
  EXPECT_EQ(json::parse(r->body)["field"], "");
}

// The library answers a too-long request line before it reads the headers; the answer still carries CORS.
TEST(HttpDetails, A414CarriesCorsHeaders) {
  auto config = softtune::http::testing::web_config();
  config.cors.origins = {"https://tools.example"};
  TestServer s(quick_options(), config);
  const std::string r = exchange(s.port(), "GET /" + std::string(limits::kMaxHeaderLineBytes + 10, 'a') +
                                               " HTTP/1.1\r\nHost: t\r\nOrigin: https://tools.example\r\n\r\n");
  EXPECT_EQ(status_of(r), 414);
  EXPECT_NE(head_of(r).find("\r\nAccess-Control-Allow-Origin: https://tools.example\r\n"), std::string::npos) << head_of(r);
}

// GET /metrics says what each cache holds: the tune responses once one is cached.
TEST(HttpDetails, MetricsReportEachCachesSize) {
  TestServer s;
  auto c = s.client();
  ASSERT_TRUE(c.Post("/api/v1/tune", kTune, "application/json"));
  auto m = c.Get("/metrics");
  ASSERT_TRUE(m);
  const std::string line = "softtune_cache_entries{cache=\"tune\"} ";
  const std::size_t at = m->body.find(line);
  ASSERT_NE(at, std::string::npos) << m->body;
  EXPECT_GE(std::stoul(m->body.substr(at + line.size())), 1u);  // the canonical request and its spelling
  EXPECT_NE(m->body.find("\nsofttune_resident_bytes "), std::string::npos);
}

}  // namespace http_details_test
