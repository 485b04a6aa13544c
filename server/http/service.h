#pragma once
// The service without the transport: the route table, the one error wrapper, metrics and the
// configuration the handlers share. The transport turns bytes into HttpRequest, calls handle(), and
// counts each finished request in metrics(); tests can call handle() directly.

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "app/preset_store.h"
#include "http/http_types.h"
#include "http/cors.h"
#include "http/limits.h"
#include "http/memory_release.h"
#include "http/metrics.h"
#include "http/response_cache.h"

namespace softtune::http {

class Service;

using Handler = std::function<HttpResponse(const HttpRequest&, Service&)>;

/// One row of the route table: method ("GET", "POST"), pattern (router.h), handler and the query
/// parameters it reads. Any other query parameter, or one of them given twice, is a 422 naming it
/// before the handler runs; {"*"} takes any query (the static page).
struct Route {
  std::string method;
  std::string pattern;
  Handler handler;
  std::vector<std::string> query = {};
};

struct ServiceConfig {
  std::filesystem::path web_root = "web";  ///< the static page's folder
  std::string presets_dir = app::resolve_presets_dir();  ///< simulate and presets: $SOFTTUNE_PRESETS, else presets/
  std::size_t cache_entries = limits::kResponseCacheEntries;  ///< 0 turns the response cache off
  std::size_t cache_bytes = limits::kResponseCacheBytes;
  CorsPolicy cors;  ///< cross-origin answers (cors.h); off by default
};

class Service {
 public:
  Service(ServiceConfig config, std::vector<Route> routes);

  /// Routes the request (HEAD as GET) and runs its handler. Never throws: a codec::Problem becomes its
  /// status as problem+json, any other exception a 500 problem; no route is 404, a wrong method 405.
  /// After a large request the allocator gives its memory back (memory_release.h). With CORS on, a
  /// preflight is answered here and every answer to an allowed Origin carries the CORS headers (cors.h).
  HttpResponse handle(HttpRequest request);

  /// The CORS headers for an answer the transport writes itself (a refused head) to a request from
  /// `origin`.
  void add_cors(const std::optional<std::string>& origin, HttpResponse& response) const {
    add_cors_headers(config_.cors, origin, response);
  }

  /// The metrics label of a request: its route's pattern, or "unmatched".
  std::string_view route_label(std::string_view method, std::string_view path) const;

  const ServiceConfig& config() const { return config_; }
  const std::vector<Route>& routes() const { return routes_; }
  Metrics& metrics() { return metrics_; }
  ResponseCache& response_cache() { return cache_; }
  const MemoryRelease& memory_release() const { return memory_; }
  double uptime_seconds() const;

 private:
  HttpResponse dispatch(HttpRequest request);
  HttpResponse preflight(const HttpRequest& request) const;
  const Route* find(std::string_view method, std::string_view path) const;
  /// "GET, POST": the methods of the exact (non-catch-all) routes matching `path`.
  std::string allowed_methods(std::string_view path) const;
  std::string path_methods(std::string_view path) const;

  ServiceConfig config_;
  std::vector<Route> routes_;
  Metrics metrics_;
  ResponseCache cache_;
  MemoryRelease memory_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace softtune::http
