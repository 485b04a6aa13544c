#pragma once
// The one registry of softtune's limits. Each limit stays a named constant beside the code that enforces it
// (server/http/limits.h, core/include/softtune/validation.h, scene/limits.h, ...); this registry reads
// those constants and is the only place that says which of them are published and how. From it come:
//   - the OpenAPI document's `info.x-softtune-limits` (http/openapi.cpp injects it into the served
//     document, so openapi.json itself holds no figure), and
//   - the limits table of docs/limits-and-security.md between `<!-- limits:begin -->` and
//     `<!-- limits:end -->`, written by the `limits_table` program (`cmake --build build --target
//     limits_doc`); ctest `docs.limits_table` fails when the page and the registry drift.
// A new limit: a constant where it is enforced, a line in numeric_limits() if tools should read it, and
// a row (or a figure in a row) of limit_rows().

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace softtune::http {

/// A limit tools read from the OpenAPI document: `key` in `info.x-softtune-limits`, in the unit its
/// suffix names (`_bytes`, `_ms`, `_s`) or a count.
struct NumericLimit {
  std::string_view key;
  double value;
};

/// One row of the documentation's limits table.
struct LimitRow {
  std::string cap;         ///< what is limited
  std::string value;       ///< the figures, written from the constants
  std::string defined_in;  ///< file and constant
  std::string above;       ///< what happens above it
};

std::vector<NumericLimit> numeric_limits();
std::vector<LimitRow> limit_rows();

/// numeric_limits() as the JSON object of `info.x-softtune-limits` (integers as integers).
nlohmann::json limits_json();
/// limit_rows() as a Markdown table (header, separator, one line per row, each ending in '\n').
std::string limits_table_markdown();

}  // namespace softtune::http
