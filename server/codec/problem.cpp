#include "codec/problem.h"

namespace softtune::codec {
namespace {

// A problem may quote the request (nlohmann's parse errors quote the bytes read last; a preset name
// comes from the path): bytes that are not UTF-8 become U+FFFD, or dumping the problem as JSON would
// throw and turn the 400 into a 500.
std::string valid_utf8(const std::string& text) {
  const std::string quoted = nlohmann::json(text).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  return nlohmann::json::parse(quoted).get<std::string>();
}

}  // namespace

Problem::Problem(int status_, std::string title_, std::string field_, std::string detail_)
    : std::runtime_error(field_.empty() ? detail_ : field_ + ": " + detail_),
      status(status_), title(std::move(title_)), field(valid_utf8(field_)), detail(valid_utf8(detail_)) {}

Problem invalid_field(std::string field, std::string rule) {
  return Problem(422, "Invalid field", std::move(field), std::move(rule));
}

Problem malformed_json(std::string detail) { return Problem(400, "Malformed JSON", "", std::move(detail)); }

nlohmann::json problem_json(const Problem& p) {
  std::string type = "/problems/";
  for (char c : p.title) type += c == ' ' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  nlohmann::json out = {{"type", type}, {"title", p.title}, {"status", p.status}, {"detail", p.detail}, {"field", p.field}};
  if (p.extensions.is_object()) {
    for (auto it = p.extensions.begin(); it != p.extensions.end(); ++it) {
      if (!out.contains(it.key())) out[it.key()] = it.value();
    }
  }
  return out;
}

}  // namespace softtune::codec
