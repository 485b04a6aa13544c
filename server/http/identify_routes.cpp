#include "http/identify_routes.h"

#include <algorithm>
#include <cctype>

#include "app/identify_app.h"
#include "codec/identify_codec.h"
#include "codec/json_reader.h"
#include "codec/problem.h"

namespace softtune::http {

bool is_csv_media_type(std::string_view content_type) {
  std::string_view type = content_type.substr(0, content_type.find(';'));
  while (!type.empty() && type.front() == ' ') type.remove_prefix(1);
  while (!type.empty() && type.back() == ' ') type.remove_suffix(1);
  constexpr std::string_view kCsv = "text/csv";
  return type.size() == kCsv.size() && std::equal(type.begin(), type.end(), kCsv.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

namespace {

// The codec reads a CSV request's query as the JSON request it spells (identify_request_from_csv): fps
// becomes request.fps and typed_k typed.k. A problem names the query parameter the client wrote.
std::string query_name(const std::string& field) {
  if (field.starts_with("request.")) return field.substr(8);
  if (field.starts_with("typed.")) return "typed_" + field.substr(6);
  return field;
}

}  // namespace

HttpResponse identify(const HttpRequest& request, Service&) {
  if (is_csv_media_type(request.header("Content-Type").value_or(""))) {
    try {
      return json_response(app::run_identify(codec::identify_request_from_csv(request.body, request.query)));
    } catch (codec::Problem& p) {
      p.field = query_name(p.field);
      throw;
    }
  }
  if (!request.query.empty()) {
    throw codec::invalid_field(request.query.begin()->first, "query parameters go with a text/csv body; in JSON, put them in the body");
  }
  return json_response(app::run_identify(codec::parse_json(request.body)));
}

}  // namespace softtune::http
