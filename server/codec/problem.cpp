#include "codec/problem.h"

namespace softtune::codec {

Problem::Problem(int status_, std::string title_, std::string field_, std::string detail_)
    : std::runtime_error(field_.empty() ? detail_ : field_ + ": " + detail_),
      status(status_), title(std::move(title_)), field(std::move(field_)), detail(std::move(detail_)) {}

Problem invalid_field(std::string field, std::string rule) {
  return Problem(422, "Invalid field", std::move(field), std::move(rule));
}

Problem malformed_json(std::string detail) { return Problem(400, "Malformed JSON", "", std::move(detail)); }

nlohmann::json problem_json(const Problem& p) {
  std::string type = "/problems/";
  for (char c : p.title) type += c == ' ' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return {{"type", type}, {"title", p.title}, {"status", p.status}, {"detail", p.detail}, {"field", p.field}};
}

}  // namespace softtune::codec
