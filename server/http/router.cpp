#include "http/router.h"

#include <vector>

namespace softtune::http {
namespace {

std::vector<std::string_view> split(std::string_view path) {
  std::vector<std::string_view> out;
  std::size_t start = 1;  // paths and patterns start with '/'
  while (start <= path.size()) {
    std::size_t end = path.find('/', start);
    if (end == std::string_view::npos) end = path.size();
    out.push_back(path.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

bool match_segment(std::string_view pattern, std::string_view segment, std::map<std::string, std::string>& captures) {
  const std::size_t open = pattern.find('{');
  if (open == std::string_view::npos) return pattern == segment;
  const std::size_t close = pattern.find('}', open);
  const std::string_view prefix = pattern.substr(0, open), suffix = pattern.substr(close + 1);
  if (segment.size() <= prefix.size() + suffix.size()) return false;
  if (segment.substr(0, prefix.size()) != prefix || segment.substr(segment.size() - suffix.size()) != suffix) return false;
  captures[std::string(pattern.substr(open + 1, close - open - 1))] =
      std::string(segment.substr(prefix.size(), segment.size() - prefix.size() - suffix.size()));
  return true;
}

}  // namespace

bool is_rest_pattern(std::string_view pattern) { return pattern.ends_with("...}"); }

std::optional<std::map<std::string, std::string>> match_route(std::string_view pattern, std::string_view path) {
  if (path.empty() || path.front() != '/' || pattern.empty()) return std::nullopt;
  std::map<std::string, std::string> captures;
  if (is_rest_pattern(pattern)) {
    const std::size_t open = pattern.rfind('{');
    const std::string_view head = pattern.substr(0, open);  // ends with '/'
    if (!path.starts_with(head)) return std::nullopt;
    captures[std::string(pattern.substr(open + 1, pattern.size() - open - 5))] = std::string(path.substr(head.size()));
    return captures;
  }
  const std::vector<std::string_view> want = split(pattern), got = split(path);
  if (want.size() != got.size()) return std::nullopt;
  for (std::size_t i = 0; i < want.size(); ++i) {
    if (!match_segment(want[i], got[i], captures)) return std::nullopt;
  }
  return captures;
}

}  // namespace softtune::http
