#include "app/preset_store.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "codec/json_reader.h"
#include "codec/json_schema.h"
#include "codec/problem.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary

namespace {

namespace fs = std::filesystem;


std::string read_text(const fs::path& path, const std::string& what) {
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) throw Problem(404, "Not found", what, "cannot read \"" + path.string() + "\"");
  if (size > kMaxPresetBytes) throw Problem(413, "Too large", what, "\"" + path.string() + "\" is larger than 4 MiB");
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > kMaxPresetNameLength || name == "schema") return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

}  // namespace

std::string resolve_presets_dir(const std::optional<std::string>& explicit_dir) {
  if (explicit_dir) return *explicit_dir;
  if (const char* env = std::getenv("SOFTTUNE_PRESETS"); env && *env) return env;
  return "presets";
}

std::vector<std::string> list_presets(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Problem(404, "Not found", "presets", "no presets directory \"" + dir + "\"");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const fs::path& p = entry.path();
    if (entry.is_regular_file() && p.extension() == ".json" && valid_name(p.stem().string())) names.push_back(p.stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

nlohmann::json load_schema(const std::string& dir) {
  const fs::path path = fs::path(dir) / "schema.json";
  try {
    return parse_json(read_text(path, "schema"));
  } catch (const Problem& p) {
    throw Problem(500, "Broken schema", "schema", path.string() + ": " + p.detail);
  }
}

nlohmann::json load_preset(const std::string& dir, const std::string& name) {
  if (!valid_name(name)) throw invalid_field("preset", "must be a preset name: 1 to 64 of a-z, 0-9, _ and - (see GET /api/v1/presets)");
  const fs::path path = fs::path(dir) / (name + ".json");
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw Problem(404, "Unknown preset", "preset", "no preset \"" + name + "\" in " + dir);
  return load_preset_file(path.string(), dir);
}

nlohmann::json load_preset_file(const std::string& path, const std::string& schema_dir) {
  nlohmann::json preset;
  try {
    preset = parse_json(read_text(path, "preset"));
  } catch (const Problem& p) {
    throw Problem(p.status, p.title, p.field, path + ": " + p.detail);
  }
  validate_preset(preset, load_schema(schema_dir), path);
  return preset;
}

void validate_preset(const nlohmann::json& preset, const nlohmann::json& schema, const std::string& file) {
  if (auto e = validate_json_schema(preset, schema)) {
    const std::string pointer = e->pointer.empty() ? "(root)" : e->pointer;
    throw Problem(422, "Invalid preset", e->pointer, file + ": " + pointer + " " + e->rule);
  }
}

}  // namespace softtune::app
