#pragma once
// Flags that map one to one onto request fields (`--damping-ratio 0.5` -> "damping_ratio": 0.5), shared
// by the commands that build a request from flags.

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "cli/cli_io.h"

namespace softtune::cli {

struct FlagField {
  const char* flag;
  const char* field;
  bool numeric;  ///< a JSON number (Problem naming the flag when it is not one); otherwise a string
};

/// The flag names of `fields`, for parse_flags().
std::vector<std::string> flag_names(std::span<const FlagField> fields);

/// Sets request[field] for every flag of `fields` that `flags` holds.
void set_fields_from_flags(const Flags& flags, std::span<const FlagField> fields, nlohmann::json& request);

}  // namespace softtune::cli
