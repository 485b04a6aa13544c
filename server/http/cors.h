#pragma once
// Cross-origin requests (the Fetch standard's CORS protocol) for studio tools served from another origin.
// Off unless `softtune serve --cors-origin ORIGIN` (repeatable, or `*`) names origins. Then every
// answer to a request whose Origin is allowed carries Access-Control-Allow-Origin (and Vary: Origin),
// errors included, and a preflight (OPTIONS with Access-Control-Request-Method) on a known path is
// answered 204 with the path's methods and the request headers a tool may send. docs/api.md "CORS".

#include <optional>
#include <string>
#include <vector>

#include "http/http_types.h"

namespace softtune::http {

/// Request headers a cross-origin tool may send (a preflight asking for others is not allowed).
inline constexpr const char* kCorsAllowedHeaders = "Content-Type, If-None-Match";
/// Response headers a cross-origin script may read besides the CORS-safelisted ones.
inline constexpr const char* kCorsExposedHeaders = "ETag, Allow, Retry-After, Location";
/// How long a browser may keep a preflight's answer, s.
inline constexpr int kCorsMaxAgeSeconds = 600;

struct CorsPolicy {
  /// Allowed origins ("https://tools.example:8443"), or "*" for any; empty: CORS off.
  std::vector<std::string> origins;

  bool enabled() const { return !origins.empty(); }
  /// True when `origin` may read the answers.
  bool allows(const std::string& origin) const;
};

/// Adds the CORS headers to an answer of a request from `origin` (its Origin header) when it is allowed.
void add_cors_headers(const CorsPolicy& policy, const std::optional<std::string>& origin, HttpResponse& response);

/// The Allow header of a path served under `methods` ("GET, POST"): those, HEAD beside GET, and OPTIONS.
/// Every answer that names a path's methods (405, OPTIONS, a preflight) says this same list.
std::string allow_list(const std::string& methods);

/// True for a CORS preflight: OPTIONS with Origin and Access-Control-Request-Method.
bool is_preflight(const HttpRequest& request);

/// The answer to a preflight on a path served under `allowed_methods` ("GET, POST"): 204 with Allow, and
/// Access-Control-Allow-Methods and -Headers and Max-Age when the origin, the method and the headers
/// asked for are allowed; else 204 without them (the browser then refuses the request itself). The
/// Allow-Origin header is add_cors_headers' (Service::handle adds it to every answer).
HttpResponse preflight_response(const CorsPolicy& policy, const HttpRequest& request, const std::string& allowed_methods);

}  // namespace softtune::http
