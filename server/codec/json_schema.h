#pragma once
// A JSON Schema validator for the subset softtune's own schemas use (presets/schema.json, the OpenAPI
// document's schemas). Debian 12 packages no C++ JSON Schema validator, so this small one is ours.
// Supported keywords: type (string or array), enum, const, properties, required, additionalProperties
// (boolean or schema), items (schema), minItems, maxItems, minimum, maximum, exclusiveMinimum,
// exclusiveMaximum, minLength, maxLength, pattern-free strings, $ref to "#/..." pointers, oneOf, anyOf,
// allOf. Unknown keywords (description, title, examples, format, ...) are ignored, as JSON Schema says.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace softtune::codec {

struct SchemaError {
  std::string pointer;  ///< JSON pointer of the offending instance location ("/joints/0/frequency_hz")
  std::string rule;     ///< what the schema asked for there
};

/// The first violation of `schema` by `instance`, or nothing. `$ref`s resolve against `schema` itself.
std::optional<SchemaError> validate_json_schema(const nlohmann::json& instance, const nlohmann::json& schema);

/// Same, resolving `$ref`s against `root` (for a sub-schema of a larger document such as OpenAPI).
std::optional<SchemaError> validate_json_schema(const nlohmann::json& instance, const nlohmann::json& schema,
                                                const nlohmann::json& root);

}  // namespace softtune::codec
