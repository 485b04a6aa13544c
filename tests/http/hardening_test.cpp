// Each hardening item of the transport against a live in-process server: bodies the library would read
// without a limit (chunked, gzip, no Content-Length, oversized), huge heads, path tricks, deep JSON,
// a full queue, slow and idle clients, a full connection gate. Every test is bounded to a few seconds.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "softtune/support/sanitizer_build.h"
#include "http/limits.h"
#include "openapi_conformance.h"
#include "test_server.h"

using nlohmann::json;
using softtune::http::testing::body_of;
using softtune::http::testing::exchange;
using softtune::http::testing::quick_options;
using softtune::http::testing::RawConnection;
using softtune::http::testing::status_of;
using softtune::http::testing::TestServer;
namespace limits = softtune::http::limits;

namespace {

const std::string kTune = R"({"response_frames": 12, "oscillation": "some", "effective_mass": 2})";


std::string field_of(const std::string& response) { return json::parse(body_of(response))["field"]; }

// Quick options with a shorter whole-request deadline and idle keep-alive timeout.
softtune::http::TransportOptions short_timeouts(int read_ms, int keep_alive_ms) {
  auto options = quick_options();
  options.request_read_timeout = std::chrono::milliseconds(read_ms);
  options.keep_alive_timeout = std::chrono::milliseconds(keep_alive_ms);
  return options;
}

}  // namespace

TEST(Hardening, ChunkedBodyIsRefusedBeforeItIsRead) {
  TestServer s;
  const std::string r = exchange(s.port(), "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                           "Transfer-Encoding: chunked\r\n\r\n" "4\r\n{\"a\"\r\n0\r\n\r\n");
  EXPECT_EQ(status_of(r), 411);
  EXPECT_EQ(field_of(r), "Transfer-Encoding");
  // The library's client sends a body of unknown length chunked.
  auto client = s.client();
  auto res = client.Post("/api/v1/tune", [](size_t, httplib::DataSink& sink) {
    sink.write(kTune.data(), kTune.size());
    sink.done();
    return true;
  }, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 411);
}

TEST(Hardening, CompressedBodyIsRefused) {
  TestServer s;
  auto client = s.client();
  client.set_compress(true);  // gzip body with Content-Encoding: gzip
  auto res = client.Post("/api/v1/tune", kTune, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 415);
  EXPECT_EQ(json::parse(res->body)["field"], "Content-Encoding");
  EXPECT_EQ(softtune::http::testing::conformance_error("/api/v1/tune", "post", 415, "application/problem+json",
                                                        json::parse(res->body)), "");
}

TEST(Hardening, PostWithoutContentLengthIsRefused) {
  TestServer s;
  const std::string r = exchange(s.port(), "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n\r\n" + kTune);
  EXPECT_EQ(status_of(r), 411);
  EXPECT_EQ(field_of(r), "Content-Length");
}

TEST(Hardening, WrongContentTypeIs415) {
  TestServer s;
  auto res = s.client().Post("/api/v1/tune", kTune, "text/plain");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 415);
  EXPECT_EQ(json::parse(res->body)["field"], "Content-Type");
}

TEST(Hardening, OversizedBodyIs413) {
  TestServer s;
  // Announced but never sent: refused from the head alone.
  const std::string r = exchange(s.port(), "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                           "Content-Length: 1073741824\r\n\r\n");
  EXPECT_EQ(status_of(r), 413);
  // With "Expect: 100-continue" the refusal comes instead of "100 Continue".
  const std::string expecting = exchange(s.port(), "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                                   "Content-Length: 5000000\r\nExpect: 100-continue\r\n\r\n");
  EXPECT_EQ(status_of(expecting), 413) << expecting;
  // Sent, one byte over the limit: the answer comes before the body is read.
  std::string body = "[" + std::string(limits::kMaxBodyBytes - 1, ' ') + "]";
  const std::string over = exchange(s.port(), "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\n"
                                              "Content-Length: " + std::to_string(body.size() + 1) + "\r\n\r\n" + body.substr(0, 4096));
  EXPECT_EQ(status_of(over), 413);
  EXPECT_EQ(field_of(over), "Content-Length");
  // At the limit the body is read and parsed (and refused for what it says, not for its size).
  body.pop_back();
  body.back() = ']';
  auto at_limit = s.client().Post("/api/v1/tune", body.substr(0, limits::kMaxBodyBytes), "application/json");
  ASSERT_TRUE(at_limit);
  EXPECT_EQ(at_limit->status, 422);
}

TEST(Hardening, HugeHeadersAre431) {
  TestServer s;
  auto client = s.client();
  httplib::Headers one_huge = {{"X-Filler", std::string(limits::kMaxHeaderBytes, 'a')}};
  auto r1 = client.Get("/api/v1/health", one_huge);
  ASSERT_TRUE(r1);
  EXPECT_EQ(r1->status, 431);
  auto one_long_line = client.Get("/api/v1/health", {{"X-Filler", std::string(limits::kMaxHeaderLineBytes + 100, 'd')}});
  ASSERT_TRUE(one_long_line);
  EXPECT_EQ(one_long_line->status, 431);
  httplib::Headers many;
  for (int i = 0; i < 40; ++i) many.emplace("X-Filler-" + std::to_string(i), std::string(500, 'b'));
  auto r2 = client.Get("/api/v1/health", many);
  ASSERT_TRUE(r2);
  EXPECT_EQ(r2->status, 431);
  EXPECT_EQ(json::parse(r2->body)["field"], "headers");
  auto fine = client.Get("/api/v1/health", {{"X-Small", std::string(1000, 'c')}});
  ASSERT_TRUE(fine);
  EXPECT_EQ(fine->status, 200);
}

TEST(Hardening, PathTricksNeverLeaveTheWebFolder) {
  TestServer s;
  for (const char* target : {"/../CMakeLists.txt", "/%2e%2e/CMakeLists.txt", "/..%2fCMakeLists.txt",
                             "/%2e%2e%2fserver%2fhttp%2flimits.h", "/index.html%00.png", "/..%5cCMakeLists.txt",
                             "/.%2e/.%2e/etc/passwd", "//etc/passwd", "/%252e%252e/CMakeLists.txt"}) {
    const std::string r = exchange(s.port(), std::string("GET ") + target + " HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n");
    EXPECT_TRUE(status_of(r) == 400 || status_of(r) == 404) << target << "\n" << r;
    EXPECT_EQ(r.find("cmake_minimum_required"), std::string::npos) << target;
    EXPECT_EQ(r.find("root:"), std::string::npos) << target;
  }
}

TEST(Hardening, DeepJsonIsRefusedWithoutCrashing) {
  TestServer s;
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  auto r = s.client().Post("/api/v1/tune", deep, "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(json::parse(r->body)["detail"].get<std::string>().find("nesting"), std::string::npos);
  const std::string nested_field = R"({"constraint": )" + std::string(100, '{') + std::string(100, '}') + "}";
  auto r2 = s.client().Post("/api/v1/tune", nested_field, "application/json");
  ASSERT_TRUE(r2);
  EXPECT_EQ(r2->status, 400);
  auto alive = s.client().Get("/api/v1/health");
  ASSERT_TRUE(alive);
  EXPECT_EQ(alive->status, 200);
}

TEST(Hardening, GetWithABodyIsRefused) {
  TestServer s;
  const std::string r = exchange(s.port(), "GET /api/v1/health HTTP/1.1\r\nHost: t\r\nContent-Length: 5\r\n\r\nhello");
  EXPECT_EQ(status_of(r), 400);
}

TEST(Hardening, ARefusedBodyIsNeverParsedAsTheNextRequest) {
  TestServer s;
  // The body of a refused request smuggles a second request; the server must close instead of reading it.
  const std::string smuggled = "GET /metrics HTTP/1.1\r\nHost: t\r\n\r\n";
  RawConnection c(s.port());
  c.send("POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: text/plain\r\nContent-Length: " +
         std::to_string(smuggled.size()) + "\r\n\r\n" + smuggled);
  const std::string r = c.receive();
  EXPECT_EQ(status_of(r), 415);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(r.find("HTTP/1.1 200"), std::string::npos) << r;
}

std::string tune_post() {
  return "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\nContent-Type: application/json\r\nConnection: close\r\n"
         "Content-Length: " + std::to_string(kTune.size()) + "\r\n\r\n" + kTune;
}

// A body still arriving holds no worker (it waits in the gate); a long request does: the default
// stability sweep (about a second) holds the only worker, one tune waits in the queue, the next is 503.
// Health is not refused: probes have their own lane.
TEST(Hardening, FullQueueAnswers503) {
  auto options = quick_options();
  options.threads = 1;
  options.max_queued = 1;
  TestServer s(options);
  RawConnection holds_the_worker(s.port());
  holds_the_worker.send("GET /api/v1/stability HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n");
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  RawConnection waits_in_the_queue(s.port());
  waits_in_the_queue.send(tune_post());
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  auto res = s.client().Post("/api/v1/tune", kTune, "application/json");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 503);
  EXPECT_EQ(res->get_header_value("Retry-After"), "1");
  EXPECT_EQ(softtune::http::testing::conformance_error("/api/v1/tune", "post", 503, "application/problem+json",
                                                        json::parse(res->body)), "");
  auto health = s.client().Get("/api/v1/health");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  // Both requests are served in the end (the default sweep takes about 70 s under ASan).
  const auto served_within = std::chrono::seconds(SOFTTUNE_SANITIZED_BUILD ? 300 : 30);
  EXPECT_EQ(status_of(holds_the_worker.receive(served_within)), 200);
  EXPECT_EQ(status_of(waits_in_the_queue.receive(served_within)), 200);
}

TEST(Hardening, SlowClientIsCutOffAtTheRequestDeadline) {
  TestServer s(short_timeouts(500, 1500));
  RawConnection slow(s.port());
  ASSERT_TRUE(slow.send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\n"));
  // One header byte every 100 ms: each read succeeds quickly, only the whole-request deadline stops it.
  const auto start = std::chrono::steady_clock::now();
  std::string answer;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(3000) && slow.send("X")) {
    answer += slow.receive(std::chrono::milliseconds(100));
    if (slow.closed()) break;
  }
  EXPECT_TRUE(slow.closed()) << "still open after 3 s";
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(2000));
  EXPECT_EQ(status_of(answer), 408) << answer;
  EXPECT_EQ(softtune::http::testing::conformance_error("/api/v1/tune", "post", 408, "application/problem+json",
                                                        json::parse(body_of(answer))), "");
}

// The gate's 408 is an answer like any other: with --cors-origin it carries the CORS headers.
TEST(Hardening, TheRequestDeadlinesAnswerCarriesCorsHeaders) {
  softtune::http::ServiceConfig config = softtune::http::testing::web_config();
  config.cors.origins = {"https://tools.example"};
  TestServer s(short_timeouts(300, 1500), config);
  RawConnection slow(s.port());
  ASSERT_TRUE(slow.send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\nOrigin: https://tools.example\r\n"));
  const std::string answer = slow.receive(std::chrono::milliseconds(2000));
  EXPECT_EQ(status_of(answer), 408) << answer;
  EXPECT_NE(answer.find("\r\nAccess-Control-Allow-Origin: https://tools.example\r\n"), std::string::npos) << answer;
}

// With one worker, clients that send their heads slowly, or keep idle connections open, must not keep
// anyone else waiting: they wait in the gate, not in a worker.
TEST(Hardening, SlowHeadsAndIdleConnectionsDoNotHoldWorkers) {
  auto options = quick_options();
  options.threads = 1;
  options.request_read_timeout = std::chrono::milliseconds(10'000);
  options.keep_alive_timeout = std::chrono::milliseconds(10'000);
  TestServer s(options);
  std::vector<std::unique_ptr<RawConnection>> slow;
  for (int i = 0; i < 100; ++i) {
    slow.push_back(std::make_unique<RawConnection>(s.port()));
    slow.back()->send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\nX-Slow: ");
  }
  RawConnection idle(s.port());
  idle.send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\n\r\n");
  EXPECT_EQ(status_of(idle.receive(std::chrono::milliseconds(300))), 200);
  EXPECT_FALSE(idle.closed());
  auto client = s.client();
  client.set_read_timeout(2, 0);  // far below the 10 s the slow and idle connections may still wait
  for (int i = 0; i < 5; ++i) {
    auto res = client.Get("/api/v1/health");
    ASSERT_TRUE(res) << "request " << i;
    EXPECT_EQ(res->status, 200);
  }
  // The idle keep-alive connection is still served when it speaks again.
  idle.send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(status_of(idle.receive()), 200);
}

// A client sending request after request on one keep-alive connection must not keep its worker from
// everyone else: with one worker and 3000 requests pipelined on one connection, another client's request
// is answered before the last of them.
TEST(Hardening, BusyKeepAliveClientDoesNotKeepTheWorker) {
  auto options = quick_options();
  options.threads = 1;
  options.keep_alive_max_requests = 100'000;
  TestServer s(options);
  RawConnection busy(s.port());
  constexpr int kPipelined = 3000;
  std::thread writer([&] {
    for (int i = 0; i < kPipelined; ++i) {
      busy.send(i + 1 < kPipelined ? "GET /api/v1/health HTTP/1.1\r\nHost: t\r\n\r\n"
                                   : "GET /api/v1/health HTTP/1.1\r\nHost: t\r\nConnection: close\r\n\r\n");
    }
  });
  std::atomic<bool> busy_started = false;
  std::string busy_answers;
  std::chrono::steady_clock::time_point busy_done;
  std::thread reader([&] {
    while (!busy.closed()) {
      busy_answers += busy.receive_some();
      busy_started = true;
    }
    busy_done = std::chrono::steady_clock::now();
  });
  while (!busy_started) std::this_thread::sleep_for(std::chrono::microseconds(100));
  auto res = s.client().Get("/api/v1/health");
  const auto other_done = std::chrono::steady_clock::now();
  writer.join();
  reader.join();
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  std::size_t answered = 0;
  for (auto at = busy_answers.find("HTTP/1.1 200"); at != std::string::npos; at = busy_answers.find("HTTP/1.1 200", at + 1)) {
    ++answered;
  }
  EXPECT_EQ(answered, static_cast<std::size_t>(kPipelined));
  EXPECT_LT(other_done, busy_done) << "the other client waited for all " << kPipelined << " pipelined requests";
}

// When the gate holds max_open_connections, a newcomer is still served: the connection that has
// waited longest makes room.
TEST(Hardening, FullGateClosesTheOldestConnection) {
  auto options = quick_options();
  options.max_open_connections = 4;
  TestServer s(options);
  std::vector<std::unique_ptr<RawConnection>> idle;
  for (int i = 0; i < 4; ++i) {
    idle.push_back(std::make_unique<RawConnection>(s.port()));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  RawConnection slow(s.port());
  slow.send("GET /api/v1/health HTTP/1.1\r\n");
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  auto res = s.client().Get("/api/v1/health");
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 200);
  // Two idle connections gave way (one to the slow head, one to the request), oldest first; the slow
  // head, newer than both, stays.
  idle[0]->receive(std::chrono::milliseconds(200));
  idle[1]->receive(std::chrono::milliseconds(200));
  idle[2]->receive(std::chrono::milliseconds(50));
  EXPECT_TRUE(idle[0]->closed());
  EXPECT_TRUE(idle[1]->closed());
  EXPECT_FALSE(idle[2]->closed());
  slow.send("Host: t\r\nConnection: close\r\n\r\n");
  EXPECT_EQ(status_of(slow.receive()), 200);
}

TEST(Hardening, IdleKeepAliveConnectionsAreClosed) {
  TestServer s(short_timeouts(1500, 300));
  RawConnection idle(s.port());
  ASSERT_TRUE(idle.send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\n\r\n"));
  const auto start = std::chrono::steady_clock::now();
  const std::string r = idle.receive(std::chrono::milliseconds(2000));
  EXPECT_EQ(status_of(r), 200);
  EXPECT_TRUE(idle.closed());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(1500));
}

TEST(Hardening, KeepAliveConnectionsServeALimitedNumberOfRequests) {
  auto options = quick_options();
  options.keep_alive_max_requests = 3;
  TestServer s(options);
  RawConnection c(s.port());
  std::string all;
  for (int i = 0; i < 3; ++i) c.send("GET /api/v1/health HTTP/1.1\r\nHost: t\r\n\r\n");
  all = c.receive(std::chrono::milliseconds(1000));
  std::size_t responses = 0;
  for (std::size_t at = all.find("HTTP/1.1 200"); at != std::string::npos; at = all.find("HTTP/1.1 200", at + 1)) ++responses;
  EXPECT_EQ(responses, 3u);
  EXPECT_TRUE(c.closed());
  EXPECT_NE(all.find("Connection: close"), std::string::npos);
}
