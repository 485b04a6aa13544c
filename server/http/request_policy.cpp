#include "http/request_policy.h"

#include <charconv>
#include <string>

#include "http/identify_routes.h"
#include "http/limits.h"

namespace softtune::http {
namespace {

bool method_has_body(const std::string& method) { return method == "POST" || method == "PUT" || method == "PATCH"; }

}  // namespace

std::optional<codec::Problem> check_request_head(const HttpRequest& head) {
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
