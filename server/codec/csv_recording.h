#pragma once
// A recording as CSV text (issue 19): a header row naming the columns, then one row per sample; the first
// column is time in seconds, every other column a probe. Strict: every row has the header's field count and
// every field is a finite number; a bad row is a 422 naming it (`rows[i].<column>`) with its line number.

#include <string>
#include <string_view>
#include <vector>

#include "softtune/identify.h"

namespace softtune::codec {

/// Largest CSV text accepted (bytes); the HTTP body limit (http/limits.h) is smaller still.
inline constexpr std::size_t kCsvMaxBytes = 8u << 20;
/// Longest column name in a header (bytes).
inline constexpr std::size_t kCsvMaxNameBytes = 64;

struct NamedRecording {
  Recording recording;
  std::vector<std::string> probe_names;  ///< the header's names after the time column
  std::string time_name = "time_s";
};

/// Reads CSV text whose dotted path in the request is `field` ("csv"). Fields are separated by commas, or
/// by tabs or semicolons when the header holds no comma. Blank lines and lines starting with '#' are skipped.
/// Checks every bound and rule of validate_recording (identify.h) before returning.
NamedRecording read_csv_recording(std::string_view text, const std::string& field);

}  // namespace softtune::codec
