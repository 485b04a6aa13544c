#include "app/answer.h"

#include "codec/problem.h"

namespace softtune::app {
namespace {

std::string_view name_of(Format f) {
  switch (f) {
    case Format::json: return "json";
    case Format::csv: return "csv";
    case Format::svg: return "svg";
  }
  return "json";
}

}  // namespace

std::string_view Answer::content_type() const {
  switch (format) {
    case Format::json: return "application/json";
    case Format::csv: return "text/csv";
    case Format::svg: return "image/svg+xml";
  }
  return "application/json";
}

Format format_named(std::string_view name, std::initializer_list<Format> allowed, const std::string& field) {
  std::string rule = "must be ";
  std::size_t i = 0;
  for (Format f : allowed) {
    if (name == name_of(f)) return f;
    rule += std::string(i == 0 ? "" : i + 1 == allowed.size() ? " or " : ", ") + std::string(name_of(f));
    ++i;
  }
  throw codec::invalid_field(field, rule);
}

}  // namespace softtune::app
