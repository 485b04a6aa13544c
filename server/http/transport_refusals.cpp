#include "http/transport_refusals.h"

#include <algorithm>
#include <cctype>

#include "codec/problem.h"
#include "http/limits.h"
#include "http/request_policy.h"

namespace softtune::http {
namespace {

// The head as the request policy sees it: method, path and every header the client sent (not the
// addresses the library adds as headers).
HttpRequest policy_head(const httplib::Request& req) {
  HttpRequest out;
  out.method = req.method;
  out.path = req.path;
  for (const auto& [name, value] : req.headers) {
    if (name == "REMOTE_ADDR" || name == "REMOTE_PORT" || name == "LOCAL_ADDR" || name == "LOCAL_PORT") continue;
    out.headers.emplace(name, value);
  }
  return out;
}

// RFC 9110 5.6.2 token characters: a method is a token.
bool is_token(std::string_view s) {
  constexpr std::string_view kSpecial = "!#$%&'*+-.^_`|~";
  if (s.empty() || s.size() > 32) return false;
  for (char c : s) {
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!alnum && kSpecial.find(c) == std::string_view::npos) return false;
  }
  return true;
}

bool served(std::string_view method) {
  for (const char* m : kServedMethods) {
    if (method == m) return true;
  }
  return false;
}

// Problems for the statuses the library produces itself, before any handler runs.
codec::Problem library_problem(int status) {
  switch (status) {
    case 400: return codec::Problem(400, "Bad request", "", "the request line or a header is malformed");
    case 413: return codec::Problem(413, "Payload too large", "Content-Length",
                                    "request bodies are limited to " + std::to_string(limits::kMaxBodyBytes) + " bytes");
    case 414: return codec::Problem(414, "URI too long", "path", "the request target is too long");
    case 404: return codec::Problem(404, "Not found", "path", "no route for this method and path");
    default: return codec::Problem(status, "HTTP error", "", "the request could not be served");
  }
}

}  // namespace

std::optional<HttpResponse> head_refusal(const httplib::Request& req) {
  if (auto problem = check_request_head(policy_head(req), req.version)) return problem_response(*problem);
  return std::nullopt;
}

HttpResponse library_refusal(int status, std::string_view method, const ConnectionState* state) {
  if (state && state->body_timed_out) {
    return problem_response(codec::Problem(408, "Request timeout", "Content-Length",
                                           "the body must arrive within " + std::to_string(limits::kBodyGrace.count()) +
                                               " ms plus Content-Length at " + std::to_string(limits::kMinBodyBytesPerSecond) +
                                               " bytes/s"));
  }
  // The library refuses a header line over its compiled-in limit with a bare 400; the bytes read
  // tell that case apart from a malformed head.
  const bool line_too_long =
      state && !state->head_done && status == 400 && state->head_bytes > limits::kMaxHeaderLineBytes;
  if (state && (state->head_overflow || line_too_long)) {
    return problem_response(codec::Problem(431, "Request header fields too large", "headers",
                                           "the request line and headers are limited to " +
                                               std::to_string(limits::kMaxHeaderBytes) + " bytes, each line to " +
                                               std::to_string(limits::kMaxHeaderLineBytes)));
  }
  if (status == 400 && is_token(method) && !served(method)) {
    std::string listed;
    for (const char* m : kServedMethods) listed += (listed.empty() ? "" : ", ") + std::string(m);
    return problem_response(codec::Problem(501, "Not implemented", "method",
                                           "the method " + std::string(method.substr(0, 32)) +
                                               " is not implemented; this server implements " + listed));
  }
  return problem_response(library_problem(status));
}

HttpResponse internal_error_refusal() {
  return problem_response(codec::Problem(500, "Internal error", "", "the request could not be served"));
}

std::optional<std::string> raw_header(std::string_view head, std::string_view name) {
  std::size_t at = head.find("\r\n");  // past the request line
  while (at != std::string_view::npos) {
    const std::size_t start = at + 2, end = head.find("\r\n", start);
    if (end == std::string_view::npos || end == start) return std::nullopt;  // a partial line, or the head's end
    const std::string_view line = head.substr(start, end - start);
    const std::size_t colon = line.find(':');
    if (colon == name.size() && std::equal(name.begin(), name.end(), line.begin(), [](char a, char b) {
          return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
        })) {
      std::string_view value = line.substr(colon + 1);
      while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
      while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
      return std::string(value);
    }
    at = end;
  }
  return std::nullopt;
}

GateRefusal gate_refusal(Refusal why, std::string_view received, const TransportOptions& options, const CorsPolicy& cors) {
  const codec::Problem p =
      why == Refusal::busy
          ? codec::Problem(503, "Service unavailable", "",
                           "the server is busy: " + std::to_string(options.max_queued) +
                               " requests are already waiting for a worker; retry shortly")
      : why == Refusal::client_limit
          ? codec::Problem(503, "Service unavailable", "",
                           "too many connections from your address: at most " +
                               std::to_string(options.max_client_connections) +
                               " open at once; close one (or reuse it with keep-alive) and retry")
          : codec::Problem(408, "Request timeout", "",
                           "the request (line, headers and body) must arrive within " +
                               std::to_string(options.request_read_timeout.count()) + " ms, the body within " +
                               std::to_string(limits::kBodyGrace.count()) + " ms plus Content-Length at " +
                               std::to_string(limits::kMinBodyBytesPerSecond) + " bytes/s");
  const std::string body = codec::problem_json(p).dump();
  GateRefusal out;
  out.status = p.status;
  const std::string_view line = received.substr(0, received.find("\r\n"));
  out.method = line.substr(0, line.find(' '));
  const std::size_t path_start = line.find(' ') == std::string_view::npos ? line.size() : line.find(' ') + 1;
  out.path = line.substr(path_start, line.find(' ', path_start) - path_start);
  std::string cors_lines;
  if (cors.enabled()) {
    HttpResponse headers;
    add_cors_headers(cors, raw_header(received, "Origin"), headers);
    for (const auto& [name, value] : headers.headers) cors_lines += name + ": " + value + "\r\n";
  }
  out.response = "HTTP/1.1 " + std::to_string(p.status) +
                 (p.status == 503 ? " Service Unavailable" : " Request Timeout") +
                 "\r\nContent-Type: application/problem+json\r\n" + (p.status == 503 ? "Retry-After: 1\r\n" : "") + cors_lines +
                 "Connection: close\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  return out;
}

}  // namespace softtune::http
