#include "http/request_policy.h"

#include <cctype>
#include <charconv>
#include <string>

#include "http/identify_routes.h"
#include "http/limits.h"

namespace softtune::http {
namespace {

bool method_has_body(const std::string& method) { return method == "POST" || method == "PUT" || method == "PATCH"; }

// RFC 9110 5.6.2: token = 1*tchar.
bool is_token(std::string_view s) {
  constexpr std::string_view kSpecial = "!#$%&'*+-.^_`|~";
  if (s.empty()) return false;
  for (char c : s) {
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!alnum && kSpecial.find(c) == std::string_view::npos) return false;
  }
  return true;
}

// RFC 9110 7.2 Host = uri-host [ ":" port ]: a reg-name or IPv4 address (unreserved, sub-delims and
// pct-encoded characters) or a bracketed IP literal, then digits after one colon.
bool is_host(std::string_view host) {
  if (host.empty() || host.size() > 255) return false;
  std::string_view name = host, port;
  if (host.front() == '[') {
    const std::size_t close = host.find(']');
    if (close == std::string_view::npos) return false;
    for (char c : host.substr(1, close - 1)) {
      if (!std::isxdigit(static_cast<unsigned char>(c)) && c != ':' && c != '.') return false;
    }
    name = {};
    const std::string_view rest = host.substr(close + 1);
    if (!rest.empty() && rest.front() != ':') return false;
    port = rest.empty() ? rest : rest.substr(1);
  } else if (const std::size_t colon = host.find(':'); colon != std::string_view::npos) {
    name = host.substr(0, colon);
    port = host.substr(colon + 1);
    if (name.empty()) return false;
  }
  for (char c : port) {
    if (c < '0' || c > '9') return false;
  }
  constexpr std::string_view kAllowed = "-._~!$&'()*+,;=%";
  for (char c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && kAllowed.find(c) == std::string_view::npos) return false;
  }
  return true;
}

std::optional<codec::Problem> check_header_fields(const HttpRequest& head, std::string_view version) {
  for (const auto& [name, value] : head.headers) {
    if (!is_token(name)) {
      std::string shown = name.substr(0, 64);
      while (!shown.empty() && (shown.back() == ' ' || shown.back() == '\t')) shown.pop_back();
      return codec::Problem(400, "Bad request", shown.empty() ? "headers" : shown,
                            "a header name must be a token, with no space before its colon (\"" + name.substr(0, 64) + ":\")");
    }
  }
  const std::size_t hosts = head.headers.count("Host");
  if (hosts > 1) return codec::Problem(400, "Bad request", "Host", "the header is given more than once; give it once");
  if (hosts == 0 && version != "HTTP/1.0") {
    return codec::Problem(400, "Bad request", "Host", "an HTTP/1.1 request must carry a Host header");
  }
  if (hosts == 1 && !is_host(*head.header("Host"))) {
    return codec::Problem(400, "Bad request", "Host", "must be a host name or address, with an optional :port");
  }
  return std::nullopt;
}

}  // namespace

std::optional<codec::Problem> check_request_head(const HttpRequest& head, std::string_view version) {
  if (auto problem = check_header_fields(head, version)) return problem;
  if (head.header("Transfer-Encoding")) {
    return codec::Problem(411, "Length required", "Transfer-Encoding",
                          "request bodies must be sent with Content-Length; Transfer-Encoding (chunked) is not accepted");
  }
  if (head.header("Content-Encoding")) {
    return codec::Problem(415, "Unsupported media type", "Content-Encoding",
                          "compressed request bodies are not accepted; send uncompressed application/json");
  }
  for (const char* name : {"Content-Type", "Content-Length"}) {
    if (head.headers.count(name) > 1) {
      return codec::Problem(400, "Bad request", name, std::string("the header is given more than once; give it once"));
    }
  }
  const std::optional<std::string> length_text = head.header("Content-Length");
  if (!length_text) {
    if (method_has_body(head.method)) {
      return codec::Problem(411, "Length required", "Content-Length", head.method + " requests must carry Content-Length");
    }
    return std::nullopt;
  }
  unsigned long long length = 0;
  const char* end = length_text->data() + length_text->size();
  const auto [ptr, ec] = std::from_chars(length_text->data(), end, length);
  if (length_text->empty() || ec != std::errc() || ptr != end) {
    return codec::Problem(400, "Bad request", "Content-Length", "must be a decimal number of bytes");
  }
  if (length > limits::kMaxBodyBytes) {
    return codec::Problem(413, "Payload too large", "Content-Length",
                          "request bodies are limited to " + std::to_string(limits::kMaxBodyBytes) + " bytes, got " +
                              std::to_string(length));
  }
  if (!method_has_body(head.method)) {
    if (length > 0) return codec::Problem(400, "Bad request", "Content-Length", head.method + " requests carry no body");
    return std::nullopt;
  }
  const std::string type = head.header("Content-Type").value_or("");
  // POST /api/v1/identify also takes a recording as CSV text (identify_routes.h).
  if (head.path == kIdentifyPath && is_csv_media_type(type)) return std::nullopt;
  if (!is_json_media_type(type)) {
    return codec::Problem(415, "Unsupported media type", "Content-Type",
                          "request bodies must be application/json, got \"" + type + "\"");
  }
  return std::nullopt;
}

}  // namespace softtune::http
