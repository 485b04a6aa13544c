#pragma once
// Plain request/response types the handlers see. Only the transport (http_transport.cpp and its
// transport_*.cpp) knows the HTTP library; every other file (routes, handlers, tests of them) works on these.

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace softtune::codec {
struct Problem;
}

namespace softtune::http {

/// Header names compare case-insensitively (RFC 9110 5.1).
struct CaseInsensitiveLess {
  bool operator()(std::string_view a, std::string_view b) const;
  using is_transparent = void;
};
using HeaderMap = std::multimap<std::string, std::string, CaseInsensitiveLess>;

struct HttpRequest {
  std::string method;  ///< "GET", "POST", ...
  std::string path;    ///< percent-decoded path, without the query ("/api/v1/tune")
  std::multimap<std::string, std::string> query;  ///< decoded query parameters
  HeaderMap headers;
  std::string body;
  std::map<std::string, std::string> params;  ///< captures of the route pattern's {name} segments
  /// True once the client has closed its connection (set by the transport; empty in tests without one).
  std::function<bool()> client_gone;

  std::optional<std::string> header(std::string_view name) const;
  std::optional<std::string> query_value(std::string_view name) const;
};

struct HttpResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
  std::vector<std::pair<std::string, std::string>> headers;  ///< extra headers (Allow, Cache-Control, ...)
  std::string_view route;  ///< set by Service::handle: the pattern of the route that answered (metrics label)
};

/// 200 (or `status`) with the document as application/json.
HttpResponse json_response(const nlohmann::json& doc, int status = 200);

/// The problem's status with {type, title, status, detail, field} as application/problem+json.
HttpResponse problem_response(const codec::Problem& problem);

/// True for "application/json", with or without parameters ("application/json; charset=utf-8").
bool is_json_media_type(std::string_view content_type);

}  // namespace softtune::http
