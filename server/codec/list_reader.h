#pragma once
// Lists of numbers of any length in a request (step_rates, damping_ratios, ...), each entry range
// checked: a Problem names the field (with its index) and the rule.

#include <optional>
#include <string_view>
#include <vector>

#include "codec/json_reader.h"
#include "codec/problem.h"

namespace softtune::codec {

/// A non-empty array of at most `max_entries` finite numbers, each in [lo, hi]; empty when absent.
std::optional<std::vector<double>> read_number_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                                    double lo, double hi, const char* unit);

/// The same for integers.
std::optional<std::vector<int>> read_integer_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                                  int lo, int hi);

/// The array of objects at `key`: each read by `read(reader, "key.i")`, then finished (its unknown fields
/// refused). Absent: "is required" when `required`, else nothing is read.
template <typename Read>
void read_object_list(ObjectReader& parent, std::string_view key, bool required, Read read) {
  const nlohmann::json* list = parent.raw(key);
  if (!list) {
    if (required) throw invalid_field(parent.field(key), "is required");
    return;
  }
  if (!list->is_array()) throw invalid_field(parent.field(key), "must be an array");
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string path = parent.field(key) + "." + std::to_string(i);
    ObjectReader r = read_object((*list)[i], path);
    read(r, path);
    r.finish();
  }
}

}  // namespace softtune::codec
