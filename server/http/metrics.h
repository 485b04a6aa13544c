#pragma once
// Request counters and latency histogram in Prometheus text format (GET /metrics):
//   softtune_requests_total{route,status}            counter
//   softtune_request_duration_seconds{route}         histogram (whole request: read, handle, write)
//   softtune_cache_hits_total{cache}, softtune_cache_misses_total{cache}   counters (the preview cache)
//   softtune_cache_entries{cache}, softtune_cache_bytes{cache}   gauges: what each cache holds now (tune
//     responses, preview frames, clips, job results), read from the sources added with add_cache_gauge
//   softtune_resident_bytes                          gauge: the process's resident set (VmRSS)
// `route` is the route pattern ("/api/v1/presets/{name}"), never the raw path, so the label set stays small.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <utility>

namespace softtune::http {

class Metrics {
 public:
  /// Upper bounds (seconds) of the latency buckets; +Inf is implied.
  static constexpr std::array<double, 14> kBucketsSeconds = {0.0001, 0.00025, 0.0005, 0.001, 0.0025, 0.005, 0.01,
                                                              0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 5.0};

  void record_request(std::string_view route, int status, double seconds);
  void record_cache(std::string_view cache, bool hit);

  struct CacheSize {
    std::size_t entries = 0;
    std::size_t bytes = 0;
  };
  /// A cache whose size each exposition reads (the source must stay valid while this Metrics is read).
  void add_cache_gauge(std::string cache, std::function<CacheSize()> source);

  /// The Prometheus text exposition (version 0.0.4).
  std::string prometheus_text() const;

 private:
  struct Histogram {
    std::array<std::uint64_t, kBucketsSeconds.size()> buckets{};  ///< non-cumulative counts per bucket
    std::uint64_t count = 0;
    double sum = 0.0;
  };
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, int>, std::uint64_t> requests_;
  std::map<std::string, Histogram> durations_;
  std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> caches_;  ///< hits, misses
  std::vector<std::pair<std::string, std::function<CacheSize()>>> gauges_;
};

}  // namespace softtune::http
