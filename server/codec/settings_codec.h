#pragma once
// An engine's settings as a request spells them: {"<setting>": number, choice or boolean}, checked against the
// engine's SettingSpecs (engines/engine_model.h: range, integer, choices; a "false"/"true" switch takes a JSON
// boolean). Shared by the tune request's engine_settings (one object per modelled engine) and a scene
// request's engine_settings (the one object of the scene's engine).

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "codec/json_reader.h"
#include "softtune/engines/engine_model.h"

namespace softtune::codec {

/// A switch: a setting whose choices are exactly "false", "true" (a request gives it as a JSON boolean).
bool is_switch_setting(const engines::SettingSpec& spec);

/// The settings in `doc` (an object at `path`), each within its spec, the specs' defaults for those it does
/// not give; refuses (422) a non-object, an unknown setting and a value outside its spec, naming
/// `path`.<setting> and the rule.
engines::SettingValues read_setting_values(const nlohmann::json& doc, const std::string& path,
                                           std::span<const engines::SettingSpec> specs);

}  // namespace softtune::codec
