#pragma once
// The simulate, presets and check use cases, shared by `softtune simulate`, `softtune check` and
// POST /api/v1/simulate, GET /api/v1/presets[/{name}]: a scene document from a preset or the request,
// run in Box2D or the core integrators (scene/), and its answer.

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "codec/json_reader.h"

namespace softtune::app {

/// A simulate request: {"preset": NAME} or {"scene": {...}} (either with an optional "tuning") or a bare
/// scene, plus the options
/// "mass_model" ("effective" | "box2d_reduced"), "frames" (bool) and "frame_stride" (1..1000).
/// Presets come from `presets_dir`; a full scene is validated against `presets_dir`/schema.json too.
nlohmann::json run_simulate(const nlohmann::json& request, const std::string& presets_dir);

/// The scene document a request names: {"preset": NAME}, {"scene": {...}}, or the request itself as a bare
/// scene without its `run_options` keys; validated against presets/schema.json. A preset or scene may come
/// with {"tuning": {...}} (app/scene_tuning.h), applied to its designer-tuned items. Marks what it read in `r`.
nlohmann::json requested_scene_document(codec::ObjectReader& r, const nlohmann::json& request, const std::string& presets_dir,
                                        std::initializer_list<const char*> run_options);

/// The same with the presets directory from resolve_presets_dir().
nlohmann::json run_simulate(const nlohmann::json& request);

/// GET /api/v1/presets: {"presets": [{"name", "description", "valid", "problem"?}]}; a preset that fails its
/// schema is listed with valid = false and the problem.
nlohmann::json presets_index(const std::string& presets_dir);
/// GET /api/v1/presets/{name}: the preset document itself.
nlohmann::json preset_document(const std::string& presets_dir, const std::string& name);

/// Runs a preset's expectations: {"name", "passed", "expectations": [{probe, metric, mass_model, value, min,
/// max, passed, note}]}.
nlohmann::json check_preset(const nlohmann::json& preset);

}  // namespace softtune::app
