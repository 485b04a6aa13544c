#pragma once
// A small JSON Schema validator: the subset presets/schema.json uses (Debian 12 packages no C++ validator).
// Supported keywords: type (name or list), properties, required, additionalProperties (false or a schema),
// items, enum, const, minimum, maximum, exclusiveMinimum, exclusiveMaximum, minItems, maxItems, minLength,
// maxLength, $ref to "#/$defs/NAME", oneOf, anyOf. Annotations ($schema, $id, title, description, default,
// examples) are ignored; any other keyword is refused so a schema never silently checks less than it says.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace softtune::codec {

struct SchemaError {
  std::string pointer;  ///< JSON pointer (RFC 6901) of the offending place in the instance, "" for the root
  std::string rule;     ///< the rule it broke, e.g. "must be one of \"box\", \"circle\", \"polygon\""
};

/// The first violation of `schema` by `instance`, or nothing. Throws std::invalid_argument when the schema
/// itself uses an unsupported keyword or a $ref that does not resolve.
std::optional<SchemaError> validate_json_schema(const nlohmann::json& instance, const nlohmann::json& schema);

}  // namespace softtune::codec
