#include "codec/scene_engine_codec.h"

#include <cstdio>
#include <string>

#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/settings_codec.h"

namespace softtune::codec {

std::string scene_engine_names(std::span<const scene::SceneBackend* const> known) {
  std::string out;
  for (const scene::SceneBackend* b : known) out += (out.empty() ? "\"" : ", \"") + std::string(b->name) + "\"";
  return out;
}

SceneEngineChoice read_scene_engine(ObjectReader& r, std::span<const scene::SceneBackend* const> known) {
  std::string name(kDefaultSceneEngine);
  if (const nlohmann::json* v = r.raw("engine")) {
    if (!v->is_string()) throw invalid_field(r.field("engine"), "must be a string: one of " + scene_engine_names(known));
    name = v->get<std::string>();
  }
  SceneEngineChoice out;
  for (const scene::SceneBackend* b : known) {
    if (b->name == name) out.backend = b;
  }
  if (!out.backend) {
    throw invalid_field(r.field("engine"), "is not a scene engine of this build: one of " + scene_engine_names(known));
  }
  if (const nlohmann::json* s = r.raw("engine_settings")) {
    if (!s->is_object()) {
      throw invalid_field(r.field("engine_settings"),
                          "must be an object {setting: value} of " + name + "'s own settings");
    }
    out.settings = read_setting_values(*s, r.field("engine_settings"), out.backend->settings);
  } else {
    for (const engines::SettingSpec& spec : out.backend->settings) out.settings.push_back(spec.default_value);
  }
  return out;
}

void apply_scene_engine(const SceneEngineChoice& choice, scene::RunOptions& options) {
  options.backend = choice.backend;
  options.engine_settings = choice.settings;
}

nlohmann::json scene_engine_json(const scene::SceneResult& result) {
  return {{"name", result.engine}, {"version", result.engine_version},
          {"settings", engine_values_json(result.engine_settings)}};
}

nlohmann::json scene_engine_json(const SceneEngineChoice& choice) {
  engines::Parameters settings;
  const auto& specs = choice.backend->settings;
  for (std::size_t i = 0; i < specs.size() && i < choice.settings.size(); ++i) {
    engines::Parameter p{specs[i].name, choice.settings[i], specs[i].unit, {}};
    if (!specs[i].choices.empty()) {
      const auto c = static_cast<std::size_t>(choice.settings[i]);
      p.choice = c < specs[i].choices.size() ? specs[i].choices[c] : std::string_view{};
    }
    settings.push_back(p);
  }
  return {{"name", choice.backend->name}, {"version", choice.backend->version},
          {"settings", engine_values_json(settings)}};
}

std::string scene_engine_key(const SceneEngineChoice& choice) {
  std::string out(choice.backend->name);
  char value[32];
  for (std::size_t i = 0; i < choice.settings.size(); ++i) {
    std::snprintf(value, sizeof value, "%.17g", choice.settings[i]);
    out += (i == 0 ? "|" : ",") + std::string(value);
  }
  return out;
}

}  // namespace softtune::codec
