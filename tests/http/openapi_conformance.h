#pragma once
// Checks a real response against the OpenAPI document: the schema of
// paths[path][method].responses[status].content[media type], resolved through $refs, via
// codec::validate_json_schema. Shared by the document's unit test and the integration tests.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "codec/json_schema.h"
#include "http/openapi.h"

namespace softtune::http::testing {

inline const nlohmann::json& openapi_document() {
  static const nlohmann::json doc = nlohmann::json::parse(openapi_text());
  return doc;
}

inline const nlohmann::json& resolve(const nlohmann::json& node) {
  if (node.is_object() && node.contains("$ref")) {
    return openapi_document().at(nlohmann::json::json_pointer(node["$ref"].get<std::string>().substr(1)));
  }
  return node;
}

/// The schema the document gives for that response, or nullptr when it documents none.
inline const nlohmann::json* response_schema(const std::string& path, const std::string& method, int status,
                                             const std::string& media_type) {
  const nlohmann::json& paths = openapi_document()["paths"];
  if (!paths.contains(path) || !paths[path].contains(method)) return nullptr;
  const nlohmann::json& responses = paths[path][method]["responses"];
  const std::string code = std::to_string(status);
  if (!responses.contains(code)) return nullptr;
  const nlohmann::json& content = resolve(responses[code])["content"];
  if (!content.contains(media_type)) return nullptr;
  return &content[media_type]["schema"];
}

/// "" when `body` conforms to the documented response, else what is wrong.
inline std::string conformance_error(const std::string& path, const std::string& method, int status,
                                     const std::string& media_type, const nlohmann::json& body) {
  const nlohmann::json* schema = response_schema(path, method, status, media_type);
  if (!schema) return "no documented " + std::to_string(status) + " " + media_type + " response for " + method + " " + path;
  if (auto e = codec::validate_json_schema(body, *schema, openapi_document())) return e->pointer + " " + e->rule;
  return "";
}

}  // namespace softtune::http::testing
