#pragma once
// Lists of numbers of any length in a request (step_rates, damping_ratios, ...), each entry range
// checked: a Problem names the field (with its index) and the rule.

#include <optional>
#include <string_view>
#include <vector>

#include "codec/json_reader.h"

namespace softtune::codec {

/// A non-empty array of at most `max_entries` finite numbers, each in [lo, hi]; empty when absent.
std::optional<std::vector<double>> read_number_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                                    double lo, double hi, const char* unit);

/// The same for integers.
std::optional<std::vector<int>> read_integer_list(ObjectReader& r, std::string_view key, std::size_t max_entries,
                                                  int lo, int hi);

}  // namespace softtune::codec
