#pragma once
// The engine of a scene request: "engine" (a scene backend's name, default "box2d_v2_4") and "engine_settings"
// ({setting: value}, that backend's own settings as it spells them, checked against its SettingSpecs), and the
// answer's "engine": {name, version, settings}. The list of backends comes from the caller (the app layer's
// registry, engines/scene_backends.h), so this codec links no engine.

#include <nlohmann/json.hpp>
#include <span>
#include <string_view>

#include "codec/json_reader.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene_world.h"

namespace softtune::codec {

/// The default engine of every scene contract.
inline constexpr std::string_view kDefaultSceneEngine = "box2d_v2_4";

/// The engine a scene request names, and its settings.
struct SceneEngineChoice {
  const scene::SceneBackend* backend = nullptr;  ///< one of `known`
  engines::SettingValues settings;               ///< indexed like backend->settings, defaults filled in
};

/// Reads "engine" and "engine_settings" from `r`: an unknown engine is refused (422 naming `engine` and
/// listing `known`), a setting the engine does not have or a value outside its range too (422 naming
/// `engine_settings.<setting>` and the rule). Absent: the default engine with its defaults.
SceneEngineChoice read_scene_engine(ObjectReader& r, std::span<const scene::SceneBackend* const> known);

/// Sets options.backend and options.engine_settings from `choice`.
void apply_scene_engine(const SceneEngineChoice& choice, scene::RunOptions& options);

/// The answer's {"name", "version", "settings"} of the engine that ran `result`.
nlohmann::json scene_engine_json(const scene::SceneResult& result);

/// The same for a choice not yet run (a preview's plan): its backend's name and version, the chosen settings.
nlohmann::json scene_engine_json(const SceneEngineChoice& choice);

/// A short canonical text of a choice ("box2d_v2_4|8,3"), for a cache key.
std::string scene_engine_key(const SceneEngineChoice& choice);

/// The names of `known`, quoted and comma-separated, for a rule ("\"box2d_v2_4\", \"mujoco\"").
std::string scene_engine_names(std::span<const scene::SceneBackend* const> known);

}  // namespace softtune::codec
