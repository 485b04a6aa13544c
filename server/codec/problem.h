#pragma once
// A request problem (RFC 9457 problem details): what every bad input turns into, on the CLI (stderr, exit
// code 2) and over HTTP (application/problem+json).

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace softtune::codec {

struct Problem : std::runtime_error {
  int status;          ///< HTTP status: 400 malformed, 413 too large, 415 content type, 422 invalid value
  std::string title;   ///< short, fixed per kind
  std::string field;   ///< dotted path of the offending field ("constraint.body_a.mass", "bodies.0.mass"; never a JSON pointer), "" for the body
  std::string detail;  ///< the rule the value broke
  /// Extension members (RFC 9457 3.2) added to the JSON beside the five above, e.g. the cost budget's
  /// "fields", "estimated_cpu_seconds" and "budget_cpu_seconds" (app/request_cost.h); an object or null.
  nlohmann::json extensions;
  Problem(int status, std::string title, std::string field, std::string detail);
};

/// 422: a field's value is missing, of the wrong type, or out of range.
Problem invalid_field(std::string field, std::string rule);
/// 400: the body is not JSON.
Problem malformed_json(std::string detail);

/// {type, title, status, detail, field} and the extension members
nlohmann::json problem_json(const Problem& p);

}  // namespace softtune::codec
