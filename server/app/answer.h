#pragma once
// What a use case answers: a JSON document, or text (CSV, SVG) with its media type. The CLI prints it,
// the HTTP routes send it; both ask for the format by name (`--format`, `?format=`).

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace softtune::app {

enum class Format { json, csv, svg };

struct Answer {
  Format format = Format::json;
  nlohmann::json json;     ///< the document, when format is json
  std::string text;        ///< the CSV or SVG text otherwise
  std::string_view content_type() const;
};

/// The format called `name` if it is one of `allowed`; otherwise a Problem (422) naming `field` with
/// the rule "must be json, csv or svg" listing the allowed ones.
Format format_named(std::string_view name, std::initializer_list<Format> allowed, const std::string& field);

}  // namespace softtune::app
