#pragma once
// A JSON Schema validator for the subset softtune's own schemas use (presets/schema.json, the OpenAPI
// document's schemas). Debian 12 packages no C++ JSON Schema validator, so this small one is ours.
// Supported keywords: type (string or array), enum, const, properties, required, additionalProperties
// (boolean or schema), items (schema), minItems, maxItems, minimum, maximum, exclusiveMinimum,
// exclusiveMaximum, minLength, maxLength, pattern (ECMA-262, unanchored), $ref to "#/..." pointers, oneOf, anyOf,
// allOf. Annotations (description, title, examples, format, ...) are ignored, as JSON Schema says; any
// other keyword would silently go unchecked, so unsupported_keywords() lists them and the tests require
// softtune's schemas to have none. When no form of a oneOf/anyOf matches, the error is about the form
// the author meant: the one a constant "type" member names, else the one that matched furthest.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

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

/// The JSON pointers (into `schema`) of keywords this validator neither checks nor knows as
/// annotations: a schema with any would be enforced only in part (a misspelt "minimun" checks nothing).
std::vector<std::string> unsupported_keywords(const nlohmann::json& schema);

}  // namespace softtune::codec
