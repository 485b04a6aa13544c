#include "http/openapi.h"

#include <nlohmann/json.hpp>
#include <string>

#include "http/limits_registry.h"

namespace softtune::http {

std::string_view openapi_source_text();  // openapi_embed.cpp, generated from openapi.json

std::string_view openapi_text() {
  // ordered_json keeps the document's key order as written; built once, on first use.
  static const std::string text = [] {
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(openapi_source_text());
    doc["info"]["x-softtune-limits"] = nlohmann::ordered_json::parse(limits_json().dump());
    return doc.dump(2) + "\n";
  }();
  return text;
}

}  // namespace softtune::http
