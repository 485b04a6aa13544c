#include "http/metrics.h"

#include <cstdio>

#include "http/memory_release.h"

namespace softtune::http {
namespace {

// Label values escape backslash, double quote and newline (Prometheus text format 0.0.4).
std::string label(std::string_view value) {
  std::string out;
  for (char c : value) {
    if (c == '\\' || c == '"') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

void Metrics::record_request(std::string_view route, int status, double seconds) {
  const std::lock_guard lock(mutex_);
  ++requests_[{std::string(route), status}];
  Histogram& h = durations_[std::string(route)];
  ++h.count;
  h.sum += seconds;
  for (std::size_t i = 0; i < kBucketsSeconds.size(); ++i) {
    if (seconds <= kBucketsSeconds[i]) {
      ++h.buckets[i];
      break;
    }
  }
}

void Metrics::record_cache(std::string_view cache, bool hit) {
  const std::lock_guard lock(mutex_);
  auto& [hits, misses] = caches_[std::string(cache)];
  ++(hit ? hits : misses);
}

void Metrics::add_cache_gauge(std::string cache, std::function<CacheSize()> source) {
  const std::lock_guard lock(mutex_);
  gauges_.emplace_back(std::move(cache), std::move(source));
}

std::string Metrics::prometheus_text() const {
  const std::lock_guard lock(mutex_);
  std::string out;
  out += "# HELP softtune_requests_total HTTP requests answered, by route pattern and status.\n";
  out += "# TYPE softtune_requests_total counter\n";
  for (const auto& [key, count] : requests_) {
    out += "softtune_requests_total{route=\"" + label(key.first) + "\",status=\"" + std::to_string(key.second) +
           "\"} " + std::to_string(count) + "\n";
  }
  out += "# HELP softtune_request_duration_seconds Time from the first byte of a request to the last byte of its response.\n";
  out += "# TYPE softtune_request_duration_seconds histogram\n";
  for (const auto& [route, h] : durations_) {
    const std::string r = "route=\"" + label(route) + "\"";
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < kBucketsSeconds.size(); ++i) {
      cumulative += h.buckets[i];
      out += "softtune_request_duration_seconds_bucket{" + r + ",le=\"" + number(kBucketsSeconds[i]) + "\"} " +
             std::to_string(cumulative) + "\n";
    }
    out += "softtune_request_duration_seconds_bucket{" + r + ",le=\"+Inf\"} " + std::to_string(h.count) + "\n";
    out += "softtune_request_duration_seconds_sum{" + r + "} " + number(h.sum) + "\n";
    out += "softtune_request_duration_seconds_count{" + r + "} " + std::to_string(h.count) + "\n";
  }
  out += "# HELP softtune_cache_hits_total Lookups answered from a cache, by cache.\n";
  out += "# TYPE softtune_cache_hits_total counter\n";
  for (const auto& [cache, counts] : caches_) {
    out += "softtune_cache_hits_total{cache=\"" + label(cache) + "\"} " + std::to_string(counts.first) + "\n";
  }
  out += "# HELP softtune_cache_misses_total Lookups a cache could not answer, by cache.\n";
  out += "# TYPE softtune_cache_misses_total counter\n";
  for (const auto& [cache, counts] : caches_) {
    out += "softtune_cache_misses_total{cache=\"" + label(cache) + "\"} " + std::to_string(counts.second) + "\n";
  }
  std::vector<std::pair<std::string, CacheSize>> sizes;
  for (const auto& [cache, source] : gauges_) sizes.emplace_back(cache, source());
  out += "# HELP softtune_cache_entries Entries a cache holds now, by cache.\n";
  out += "# TYPE softtune_cache_entries gauge\n";
  for (const auto& [cache, size] : sizes) {
    out += "softtune_cache_entries{cache=\"" + label(cache) + "\"} " + std::to_string(size.entries) + "\n";
  }
  out += "# HELP softtune_cache_bytes Bytes a cache holds now, by cache.\n";
  out += "# TYPE softtune_cache_bytes gauge\n";
  for (const auto& [cache, size] : sizes) {
    out += "softtune_cache_bytes{cache=\"" + label(cache) + "\"} " + std::to_string(size.bytes) + "\n";
  }
  out += "# HELP softtune_resident_bytes The process's resident set size (VmRSS).\n";
  out += "# TYPE softtune_resident_bytes gauge\n";
  out += "softtune_resident_bytes " + std::to_string(resident_bytes()) + "\n";
  return out;
}

}  // namespace softtune::http
