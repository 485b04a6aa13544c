// The service's own cost per request, without sockets: what `softtune serve` adds on top of the
// transport for POST /api/v1/tune (a cache hit and a miss), GET /api/v1/health, and the metrics and
// route lookup every request pays. bench/http_bench.sh measures the whole server against bare
// cpp-httplib; this one shows where the time goes.
#include <benchmark/benchmark.h>

#include "http/routes.h"

namespace {

using softtune::http::HttpRequest;
using softtune::http::Service;

HttpRequest tune_request(int frames) {
  HttpRequest r;
  r.method = "POST";
  r.path = "/api/v1/tune";
  r.headers.emplace("Content-Type", "application/json");
  r.body = R"({"response_frames": )" + std::to_string(frames) +
           R"(, "oscillation": "some", "effective_mass": 2, "fps": 60, "mode": "exact"})";
  return r;
}

void BM_TuneCacheHit(benchmark::State& state) {
  Service service({}, softtune::http::service_routes());
  const HttpRequest request = tune_request(12);
  service.handle(request);
  for (auto _ : state) benchmark::DoNotOptimize(service.handle(request));
}
BENCHMARK(BM_TuneCacheHit);

void BM_TuneUncached(benchmark::State& state) {
  softtune::http::ServiceConfig config;
  config.cache_entries = 0;
  Service service(config, softtune::http::service_routes());
  const HttpRequest request = tune_request(12);
  for (auto _ : state) benchmark::DoNotOptimize(service.handle(request));
}
BENCHMARK(BM_TuneUncached);

void BM_Health(benchmark::State& state) {
  Service service({}, softtune::http::service_routes());
  HttpRequest request;
  request.method = "GET";
  request.path = "/api/v1/health";
  for (auto _ : state) benchmark::DoNotOptimize(service.handle(request));
}
BENCHMARK(BM_Health);

void BM_RecordRequest(benchmark::State& state) {
  Service service({}, softtune::http::service_routes());
  for (auto _ : state) service.metrics().record_request(service.route_label("POST", "/api/v1/tune"), 200, 0.0001);
}
BENCHMARK(BM_RecordRequest);

}  // namespace

BENCHMARK_MAIN();
