#include "http/service.h"

#include <algorithm>
#include <cstdio>

#include "app/budgets.h"
#include "codec/problem.h"
#include "http/limits.h"
#include "softtune/support/run_limit.h"
#include "softtune/support/sanitizer_build.h"
#include "http/cors.h"
#include "http/memory_release.h"
#include "http/router.h"

namespace softtune::http {
namespace {

std::string_view routing_method(std::string_view method) { return method == "HEAD" ? "GET" : method; }

// A query parameter the route does not read would be ignored silently (as unknown body fields are not),
// and a repeated one would leave which value counts to chance.
void check_query(const Route& route, const HttpRequest& request) {
  for (auto it = request.query.begin(); it != request.query.end(); it = request.query.upper_bound(it->first)) {
    if (request.query.count(it->first) > 1) {
      throw codec::invalid_field(it->first.substr(0, 64), "is given more than once; give it once");
    }
  }
  if (route.query.size() == 1 && route.query.front() == "*") return;
  for (auto it = request.query.begin(); it != request.query.end(); it = request.query.upper_bound(it->first)) {
    const std::string name = it->first.substr(0, 64);
    if (std::find(route.query.begin(), route.query.end(), it->first) == route.query.end()) {
      std::string known;
      for (const std::string& q : route.query) known += (known.empty() ? "" : ", ") + q;
      throw codec::invalid_field(name, "is not a query parameter of " + route.pattern +
                                           (known.empty() ? " (it takes none)" : " (it takes " + known + ")"));
    }
  }
}

// A request stopped while it ran: over its limit it is over budget (422, as an estimate over it would
// have been); a client that has gone reads no answer (503 for the log).
codec::Problem run_stopped_problem(const support::RunStopped& stopped) {
  if (stopped.why == support::RunStopped::Why::budget) {
    char detail[200];
    std::snprintf(detail, sizeof detail,
                  "the request was stopped after %.2f s of CPU time, past %.0f x its budget of %.0f s; its estimate "
                  "was below the budget, so ask for less (fewer frames, bodies or iterations) or run it as a job",
                  stopped.cpu_seconds, limits::kRunLimitFactor, app::budgets::kCpuSeconds);
    return codec::Problem(422, "Request over budget", "", detail);
  }
  return codec::Problem(503, "Service unavailable", "", "the client closed the connection; the work was stopped");
}

}  // namespace

Service::Service(ServiceConfig config, std::vector<Route> routes)
    : config_(std::move(config)), routes_(std::move(routes)), cache_(config_.cache_entries, config_.cache_bytes) {
  configure_allocator();
  metrics_.add_cache_gauge("tune", [this] { return Metrics::CacheSize{cache_.entries(), cache_.bytes()}; });
}

// Exact patterns first; when the path has routes only under other methods, nothing (405 follows); the
// static catch-all last, so GET /api/v1/tune is "405, use POST" and not "no such file".
const Route* Service::find(std::string_view method, std::string_view path) const {
  method = routing_method(method);
  for (const Route& r : routes_) {
    if (!is_rest_pattern(r.pattern) && r.method == method && match_route(r.pattern, path)) return &r;
  }
  if (!allowed_methods(path).empty()) return nullptr;
  for (const Route& r : routes_) {
    if (is_rest_pattern(r.pattern) && r.method == method && match_route(r.pattern, path)) return &r;
  }
  return nullptr;
}

std::string Service::allowed_methods(std::string_view path) const {
  std::string allow;
  for (const Route& r : routes_) {
    if (!is_rest_pattern(r.pattern) && match_route(r.pattern, path) && allow.find(r.method) == std::string::npos) {
      allow += (allow.empty() ? "" : ", ") + r.method;
    }
  }
  return allow;
}

std::string_view Service::route_label(std::string_view method, std::string_view path) const {
  const Route* r = find(method, path);
  return r ? std::string_view(r->pattern) : std::string_view("unmatched");
}

double Service::uptime_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

HttpResponse Service::handle(HttpRequest request) {
  const auto start = std::chrono::steady_clock::now();
  memory_.enter();
  const std::optional<std::string> origin = request.header("Origin");
  HttpResponse response = config_.cors.enabled() && is_preflight(request) ? preflight(request) : dispatch(std::move(request));
  add_cors(origin, response);
  memory_.leave(std::chrono::steady_clock::now() - start, response.body.size());
  return response;
}

// The methods of the path's exact routes, or GET for a static file (not under /api/, where a path
// without a route is no resource); empty when nothing serves the path.
std::string Service::path_methods(std::string_view path) const {
  std::string allow = allowed_methods(path);
  if (allow.empty() && !path.starts_with("/api/") && find("GET", path)) allow = "GET";
  return allow;
}

// A preflight names the path it will ask: the methods of its exact routes, or GET for a static file.
HttpResponse Service::preflight(const HttpRequest& request) const {
  const std::string allow = path_methods(request.path);
  if (allow.empty()) {
    return problem_response(codec::Problem(404, "Not found", "path", "no route for " + request.path));
  }
  return preflight_response(config_.cors, request, allow);
}

HttpResponse Service::dispatch(HttpRequest request) {
  try {
    if (const Route* r = find(request.method, request.path)) {
      check_query(*r, request);
      request.params = *match_route(r->pattern, request.path);
      const support::ScopedRunLimit limit(
          {limits::kRunLimitFactor * app::budgets::kCpuSeconds * support::kInstrumentationSlowdown, nullptr,
           request.client_gone});
      HttpResponse response = r->handler(request, *this);
      response.route = r->pattern;
      return response;
    }
    if (const std::string allow = path_methods(request.path); !allow.empty()) {
      // OPTIONS without a preflight's headers (or with CORS off) asks what the path allows (RFC 9110 9.3.7).
      if (request.method == "OPTIONS") {
        HttpResponse res;
        res.status = 204;
        res.content_type.clear();
        res.headers.emplace_back("Allow", allow_list(allow));
        return res;
      }
      HttpResponse res = problem_response(codec::Problem(405, "Method not allowed", "method",
                                                         request.method + " is not allowed here; use " + allow));
      res.headers.emplace_back("Allow", allow_list(allow));
      return res;
    }
    throw codec::Problem(404, "Not found", "path", "no route for " + request.method + " " + request.path);
  } catch (const codec::Problem& p) {
    return problem_response(p);
  } catch (const support::RunStopped& stopped) {
    return problem_response(run_stopped_problem(stopped));
  } catch (const std::exception& e) {
    return problem_response(codec::Problem(500, "Internal error", "", e.what()));
  } catch (...) {
    return problem_response(codec::Problem(500, "Internal error", "", "unknown exception"));
  }
}

}  // namespace softtune::http
