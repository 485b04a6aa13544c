#include "http/cors.h"

#include <algorithm>
#include <sstream>

namespace softtune::http {
namespace {

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

std::string lowered(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), lower);
  return s;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// Every comma-separated name in `asked` is one of kCorsAllowedHeaders (names compare case-insensitively).
bool headers_allowed(const std::string& asked) {
  const std::string allowed = lowered(kCorsAllowedHeaders);
  std::stringstream names(asked);
  std::string name;
  while (std::getline(names, name, ',')) {
    name = lowered(trimmed(name));
    if (name.empty()) continue;
    bool found = false;
    std::stringstream list(allowed);
    std::string a;
    while (std::getline(list, a, ',')) found = found || trimmed(a) == name;
    if (!found) return false;
  }
  return true;
}

bool method_listed(const std::string& methods, const std::string& method) {
  std::stringstream list(methods);
  std::string m;
  while (std::getline(list, m, ',')) {
    if (trimmed(m) == method) return true;
  }
  return false;
}

}  // namespace

bool CorsPolicy::allows(const std::string& origin) const {
  return std::any_of(origins.begin(), origins.end(), [&](const std::string& o) { return o == "*" || o == origin; });
}

void add_cors_headers(const CorsPolicy& policy, const std::optional<std::string>& origin, HttpResponse& response) {
  if (!policy.enabled() || !origin || !policy.allows(*origin)) return;
  const bool any = std::find(policy.origins.begin(), policy.origins.end(), "*") != policy.origins.end();
  response.headers.emplace_back("Access-Control-Allow-Origin", any ? "*" : *origin);
  if (!any) response.headers.emplace_back("Vary", "Origin");
  response.headers.emplace_back("Access-Control-Expose-Headers", kCorsExposedHeaders);
}

std::string allow_list(const std::string& methods) {
  return methods + (method_listed(methods, "GET") ? ", HEAD" : "") + ", OPTIONS";
}

bool is_preflight(const HttpRequest& request) {
  return request.method == "OPTIONS" && request.header("Origin") && request.header("Access-Control-Request-Method");
}

HttpResponse preflight_response(const CorsPolicy& policy, const HttpRequest& request, const std::string& allowed_methods) {
  HttpResponse r;
  r.status = 204;
  r.content_type.clear();
  const std::string methods = allow_list(allowed_methods);
  r.headers.emplace_back("Allow", methods);
  const std::string asked_method = request.header("Access-Control-Request-Method").value_or("");
  const std::string asked_headers = request.header("Access-Control-Request-Headers").value_or("");
  const std::string origin = request.header("Origin").value_or("");
  if (!policy.allows(origin) || !method_listed(methods, asked_method) || !headers_allowed(asked_headers)) return r;
  r.headers.emplace_back("Access-Control-Allow-Methods", methods);
  r.headers.emplace_back("Access-Control-Allow-Headers", kCorsAllowedHeaders);
  r.headers.emplace_back("Access-Control-Max-Age", std::to_string(kCorsMaxAgeSeconds));
  return r;
}

}  // namespace softtune::http
