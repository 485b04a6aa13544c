#pragma once
// Presets: JSON scene files in a directory (presets/ by default), each validated against the directory's
// schema.json on load. Shared by the CLI (`simulate --preset`, `check`) and the HTTP routes.

#include <nlohmann/json.hpp>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace softtune::app {

/// Largest preset file read (413 above) and longest preset name ([a-z0-9_-], not "schema").
inline constexpr std::size_t kMaxPresetBytes = std::size_t{4} << 20;
inline constexpr std::size_t kMaxPresetNameLength = 64;

/// The presets directory: `explicit_dir` if given, else $SOFTTUNE_PRESETS, else "presets" (relative to the
/// current directory).
std::string resolve_presets_dir(const std::optional<std::string>& explicit_dir = std::nullopt);

/// Names of the presets in `dir` (file names without ".json", schema.json left out), sorted.
std::vector<std::string> list_presets(const std::string& dir);

/// Reads and parses `dir`/schema.json.
nlohmann::json load_schema(const std::string& dir);

/// Loads preset NAME from `dir`: name checked ([a-z0-9_-], no path tricks; 404 when absent), JSON parsed
/// strictly, then validate_preset against the directory's schema.
nlohmann::json load_preset(const std::string& dir, const std::string& name);

/// Loads the preset in file `path` (any name), validated against `schema_dir`/schema.json: a studio's preset
/// kept outside a presets directory (`softtune check FILE`).
nlohmann::json load_preset_file(const std::string& path, const std::string& schema_dir);

/// Refuses (Problem 422, "Invalid preset") a preset that breaks `schema`: the detail names `file`, the JSON
/// pointer and the rule; `field` carries the JSON pointer.
void validate_preset(const nlohmann::json& preset, const nlohmann::json& schema, const std::string& file);

}  // namespace softtune::app
