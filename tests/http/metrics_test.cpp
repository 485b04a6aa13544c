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
