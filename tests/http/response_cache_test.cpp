#include "http/response_cache.h"

#include <gtest/gtest.h>

#include "http/routes.h"

using softtune::http::ResponseCache;

namespace {

std::shared_ptr<const std::string> text(std::string s) { return std::make_shared<const std::string>(std::move(s)); }

softtune::http::HttpResponse post_tune(softtune::http::Service& service, std::string body) {
  softtune::http::HttpRequest r;
  r.method = "POST";
  r.path = "/api/v1/tune";
  r.body = std::move(body);
  return service.handle(r);
}

}  // namespace

TEST(ResponseCache, EvictsTheLeastRecentlyUsedEntry) {
  ResponseCache cache(2, 1 << 20);
  cache.insert("a", text("A"));
  cache.insert("b", text("B"));
  ASSERT_TRUE(cache.find("a"));  // "b" is now the least recently used
  cache.insert("c", text("C"));
  EXPECT_EQ(cache.entries(), 2u);
  EXPECT_EQ(*cache.find("a"), "A");
  EXPECT_EQ(cache.find("b"), nullptr);
  EXPECT_EQ(*cache.find("c"), "C");
}

TEST(ResponseCache, KeepsWithinItsByteBound) {
  ResponseCache cache(100, 40);
  cache.insert("k1", text(std::string(8, 'x')));   // 10 bytes
  cache.insert("k2", text(std::string(8, 'y')));   // 20
  cache.insert("k3", text(std::string(8, 'z')));   // 30
  cache.insert("k4", text(std::string(8, 'w')));   // 40
  cache.insert("k5", text(std::string(8, 'v')));   // 50 -> k1 goes
  EXPECT_LE(cache.bytes(), 40u);
  EXPECT_EQ(cache.find("k1"), nullptr);
  EXPECT_TRUE(cache.find("k5"));
  cache.insert("huge", text(std::string(20, 'h')));  // over a quarter of the bound: not stored
  EXPECT_EQ(cache.find("huge"), nullptr);
}

TEST(ResponseCache, ReplacingAnEntryKeepsTheByteCount) {
  ResponseCache cache(10, 1000);
  cache.insert("k", text("12345"));
  cache.insert("k", text("123"));
  EXPECT_EQ(cache.entries(), 1u);
  EXPECT_EQ(cache.bytes(), 4u);
  EXPECT_EQ(*cache.find("k"), "123");
}

TEST(ResponseCache, TuneAnswersEqualRequestsFromTheCacheAndOthersFresh) {
  softtune::http::Service service({}, softtune::http::service_routes());
  auto post = [&](std::string body) { return post_tune(service, std::move(body)); };
  const auto first = post(R"({"response_frames": 12, "oscillation": "free", "effective_mass": 2})");
  // The same request written differently (key order, spacing, 2 vs 2.0) is the same canonical request.
  const auto again = post(R"({ "effective_mass": 2.0, "oscillation": "free", "response_frames": 12 })");
  const auto other = post(R"({"response_frames": 6, "oscillation": "free", "effective_mass": 2})");
  ASSERT_EQ(first.status, 200);
  EXPECT_EQ(again.body, first.body);
  // 6 frames at 60 fps is 10 Hz, 12 frames 5 Hz: a cache that mixed them up would fail here.
  EXPECT_NEAR(nlohmann::json::parse(other.body)["frequency_hz"].get<double>(), 10.0, 1e-12);
  EXPECT_NEAR(nlohmann::json::parse(first.body)["frequency_hz"].get<double>(), 5.0, 1e-12);
  const std::string metrics = service.metrics().prometheus_text();
  EXPECT_NE(metrics.find("softtune_cache_hits_total{cache=\"tune\"} 1\n"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("softtune_cache_misses_total{cache=\"tune\"} 2\n"), std::string::npos) << metrics;
  // Refused requests are never cached.
  EXPECT_EQ(post(R"({"response_frames": 12, "oscillation": "free"})").status, 422);
  EXPECT_EQ(post(R"({"response_frames": 12, "oscillation": "free"})").status, 422);
}

// A repeat of the same bytes is found by its bytes, without parsing (routes.cpp): each distinct spelling
// adds one entry next to the canonical one, and bodies that differ in one byte are never mixed up.
TEST(ResponseCache, RepeatedBytesAreFoundWithoutParsingAndNeverMixedUp) {
  softtune::http::Service service({}, softtune::http::service_routes());
  auto post = [&](std::string body) { return post_tune(service, std::move(body)); };
  const std::string request = R"({"response_frames": 12, "oscillation": "free", "effective_mass": 2})";
  const auto first = post(request);
  ASSERT_EQ(first.status, 200);
  EXPECT_EQ(service.response_cache().entries(), 2u);  // the canonical request and these bytes
  EXPECT_EQ(post(request).body, first.body);
  EXPECT_EQ(service.response_cache().entries(), 2u);
  EXPECT_EQ(post(request + " ").body, first.body);  // another spelling: a canonical hit, one more entry
  EXPECT_EQ(service.response_cache().entries(), 3u);
  std::string ten_frames = request;
  ten_frames.replace(ten_frames.find("12"), 2, "10");  // one byte apart: 6 Hz, not 5
  EXPECT_NEAR(nlohmann::json::parse(post(ten_frames).body)["frequency_hz"].get<double>(), 6.0, 1e-12);
  EXPECT_NEAR(nlohmann::json::parse(post(request).body)["frequency_hz"].get<double>(), 5.0, 1e-12);
  const std::string metrics = service.metrics().prometheus_text();
  EXPECT_NE(metrics.find("softtune_cache_hits_total{cache=\"tune\"} 3\n"), std::string::npos) << metrics;
  EXPECT_NE(metrics.find("softtune_cache_misses_total{cache=\"tune\"} 2\n"), std::string::npos) << metrics;
}
