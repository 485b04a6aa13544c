#include "http/http_types.h"

#include <algorithm>

#include "codec/problem.h"

namespace softtune::http {
namespace {

// ASCII only, without the locale lookup of std::tolower: header names are ASCII (RFC 9110 5.1).
char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

bool CaseInsensitiveLess::operator()(std::string_view a, std::string_view b) const {
  return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                      [](char x, char y) { return lower(x) < lower(y); });
}

std::optional<std::string> HttpRequest::header(std::string_view name) const {
  auto it = headers.find(name);
  if (it == headers.end()) return std::nullopt;
  return it->second;
}

std::optional<std::string> HttpRequest::query_value(std::string_view name) const {
  auto it = query.find(std::string(name));
  if (it == query.end()) return std::nullopt;
  return it->second;
}

HttpResponse json_response(const nlohmann::json& doc, int status) {
  HttpResponse r;
  r.status = status;
  r.body = doc.dump();
  return r;
}

HttpResponse problem_response(const codec::Problem& problem) {
  HttpResponse r;
  r.status = problem.status;
  r.content_type = "application/problem+json";
  r.body = codec::problem_json(problem).dump();
  return r;
}

bool is_json_media_type(std::string_view content_type) {
  const std::string_view type = trim(content_type.substr(0, content_type.find(';')));
  constexpr std::string_view kJson = "application/json";
  return type.size() == kJson.size() &&
         std::equal(type.begin(), type.end(), kJson.begin(), [](char a, char b) { return lower(a) == b; });
}

}  // namespace softtune::http
