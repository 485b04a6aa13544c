#include "http/metrics.h"

#include <gtest/gtest.h>

using softtune::http::Metrics;

namespace {

bool has_line(const std::string& text, const std::string& line) { return text.find(line + "\n") != std::string::npos; }

}  // namespace

TEST(Metrics, CountsRequestsByRouteAndStatus) {
  Metrics m;
  m.record_request("/api/v1/tune", 200, 0.002);
  m.record_request("/api/v1/tune", 200, 0.0004);
  m.record_request("/api/v1/tune", 422, 0.0001);
  const std::string t = m.prometheus_text();
  EXPECT_TRUE(has_line(t, "# TYPE softtune_requests_total counter"));
  EXPECT_TRUE(has_line(t, R"(softtune_requests_total{route="/api/v1/tune",status="200"} 2)"));
  EXPECT_TRUE(has_line(t, R"(softtune_requests_total{route="/api/v1/tune",status="422"} 1)"));
}

TEST(Metrics, HistogramBucketsAreCumulative) {
  Metrics m;
  m.record_request("/r", 200, 0.00005);  // <= 0.0001
  m.record_request("/r", 200, 0.003);    // <= 0.005
  m.record_request("/r", 200, 100.0);    // only +Inf
  const std::string t = m.prometheus_text();
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_bucket{route="/r",le="0.0001"} 1)"));
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_bucket{route="/r",le="0.0025"} 1)"));
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_bucket{route="/r",le="0.005"} 2)"));
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_bucket{route="/r",le="5"} 2)"));
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_bucket{route="/r",le="+Inf"} 3)"));
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_count{route="/r"} 3)"));
  EXPECT_TRUE(has_line(t, R"(softtune_request_duration_seconds_sum{route="/r"} 100.00305)"));
}

TEST(Metrics, CountsCacheHitsAndMisses) {
  Metrics m;
  m.record_cache("preview", true);
  m.record_cache("preview", true);
  m.record_cache("preview", false);
  const std::string t = m.prometheus_text();
  EXPECT_TRUE(has_line(t, R"(softtune_cache_hits_total{cache="preview"} 2)"));
  EXPECT_TRUE(has_line(t, R"(softtune_cache_misses_total{cache="preview"} 1)"));
}

TEST(Metrics, EscapesLabelValues) {
  Metrics m;
  m.record_request("a\"b\\c\nd", 200, 0.001);
  EXPECT_TRUE(has_line(m.prometheus_text(), R"(softtune_requests_total{route="a\"b\\c\nd",status="200"} 1)"));
}

// Each cache's size is read from its source at every exposition; the resident set comes with them.
TEST(Metrics, ReportsEachCachesEntriesAndBytes) {
  softtune::http::Metrics m;
  std::size_t entries = 3, bytes = 4096;
  m.add_cache_gauge("tune", [&] { return softtune::http::Metrics::CacheSize{entries, bytes}; });
  std::string text = m.prometheus_text();
  EXPECT_NE(text.find("softtune_cache_entries{cache=\"tune\"} 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("softtune_cache_bytes{cache=\"tune\"} 4096\n"), std::string::npos) << text;
  entries = 0;
  bytes = 0;
  text = m.prometheus_text();
  EXPECT_NE(text.find("softtune_cache_bytes{cache=\"tune\"} 0\n"), std::string::npos) << text;
  const std::size_t at = text.find("\nsofttune_resident_bytes ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_GT(std::stoull(text.substr(at + 25)), 1u << 20);  // a test process holds more than 1 MiB
}
