#pragma once
// The scene engine flags every scene command shares: `--engine NAME` (the request's "engine") and
// `--engine-settings name=value,name=value` (its "engine_settings": a number, true / false for a switch, or a
// choice's name; the request's codec checks them against the engine's own settings).

#include <nlohmann/json.hpp>
#include <vector>
#include <string>

#include "cli/cli_io.h"

namespace softtune::cli {

/// The flag names, for parse_flags()'s with_value list.
inline const std::vector<std::string> kEngineFlags = {"engine", "engine-settings"};

/// Sets request["engine"] and request["engine_settings"] from the flags `flags` holds; a malformed
/// --engine-settings item is a Problem naming `--engine-settings`.
void set_engine_from_flags(const Flags& flags, nlohmann::json& request);

/// `with_value` with kEngineFlags appended.
std::vector<std::string> with_engine_flags(std::vector<std::string> with_value);

}  // namespace softtune::cli
