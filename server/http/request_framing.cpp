#include "http/request_framing.h"

#include <algorithm>
#include <cctype>

namespace softtune::http {
namespace {

bool same_name(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// A Content-Length value as RFC 9110 8.6 spells it (1*DIGIT), or nullopt (also past 20 digits).
std::optional<std::size_t> decimal(std::string_view v) {
  if (v.empty() || v.size() > 19) return std::nullopt;
  std::size_t n = 0;
  for (char c : v) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + static_cast<std::size_t>(c - '0');
  }
  return n;
}

}  // namespace

std::optional<std::size_t> head_size(std::string_view received) {
  const std::size_t end = received.find("\r\n\r\n");
  if (end == std::string_view::npos) return std::nullopt;
  return end + 4;
}

std::optional<std::size_t> request_size(std::string_view received, std::size_t max_body_bytes) {
  const std::optional<std::size_t> head = head_size(received);
  if (!head) return std::nullopt;
  std::optional<std::size_t> length;
  int lengths = 0;
  std::size_t at = received.find("\r\n");  // past the request line
  while (at + 2 < *head) {
    const std::size_t start = at + 2, end = received.find("\r\n", start);
    const std::string_view line = received.substr(start, end - start);
    if (line.empty()) break;  // the blank line that ends the head
    at = end;
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) return *head;  // malformed: the worker answers 400
    const std::string_view name = line.substr(0, colon);
    // "Transfer-Encoding : chunked" is refused by the worker; a name with spaces never frames a body here.
    if (name.find_first_of(" \t") != std::string_view::npos) return *head;
    if (same_name(name, "Transfer-Encoding") || same_name(name, "Expect")) return *head;
    if (same_name(name, "Content-Length")) {
      ++lengths;
      length = decimal(trim(line.substr(colon + 1)));
    }
  }
  if (lengths != 1 || !length || *length > max_body_bytes) return *head;
  return *head + *length;
}

bool is_lane_request(std::string_view received) {
  const std::string_view line = received.substr(0, received.find("\r\n"));
  for (std::string_view method : {"GET ", "HEAD "}) {
    if (!line.starts_with(method)) continue;
    const std::string_view target = line.substr(method.size(), line.find(' ', method.size()) - method.size());
    for (std::string_view path : {"/api/v1/health", "/metrics"}) {
      if (target == path || (target.starts_with(path) && target[path.size()] == '?')) return true;
    }
  }
  return false;
}

}  // namespace softtune::http
