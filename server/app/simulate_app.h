#pragma once
// The simulate, presets and check use cases, shared by `softtune simulate`, `softtune check` and
// POST /api/v1/simulate, GET /api/v1/presets[/{name}]: a scene document from a preset or the request,
// run in Box2D or the core integrators (scene/), and its answer.

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

#include "codec/json_reader.h"
#include "codec/problem.h"
#include "codec/scene_engine_codec.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// A simulate request: {"preset": NAME} or {"scene": {...}} (either with an optional "tuning") or a bare
/// scene, plus the options
/// "mass_model" ("effective" | "box2d_reduced"), "frames" (bool), "frame_stride" (1..1000), "engine" (a
/// registered scene backend, default "box2d_v2_4") and "engine_settings" ({setting: value} of that engine).
/// Presets come from `presets_dir`; a full scene is validated against `presets_dir`/schema.json too.
nlohmann::json run_simulate(const nlohmann::json& request, const std::string& presets_dir);

/// The scene document a request names: {"preset": NAME}, {"scene": {...}}, or the request itself as a bare
/// scene without its `run_options` keys; validated against presets/schema.json. A preset or scene may come
/// with {"tuning": {...}} (app/scene_tuning.h), applied to its designer-tuned items. Marks what it read in `r`.
nlohmann::json requested_scene_document(codec::ObjectReader& r, const nlohmann::json& request, const std::string& presets_dir,
                                        std::initializer_list<const char*> run_options);

/// decode_scene, with `prefix` ("scene." for a request's "scene" key, "" for a bare scene or a preset)
/// before the field of any problem, so the field is the dotted path in the request.
scene::Scene decode_requested_scene(const nlohmann::json& scene_doc, const std::string& prefix);
/// `p` with `prefix` before its field ("scene." + "world.fps"; the prefix alone, without its dot, for a
/// problem about the whole document).
codec::Problem prefixed(const codec::Problem& p, const std::string& prefix);

/// The keys of a simulate request that are not the scene's (a bare scene's document is the request without them).
inline constexpr std::initializer_list<const char*> kSceneRunOptions = {"frames", "frame_stride", "engine", "engine_settings"};

/// The request's "engine" and "engine_settings", read against the registered scene backends
/// (engines/scene_backends.h): 422 naming `engine` (and listing them) or `engine_settings.<setting>`.
codec::SceneEngineChoice read_request_engine(codec::ObjectReader& r);

/// The same with the presets directory from resolve_presets_dir().
nlohmann::json run_simulate(const nlohmann::json& request);

/// GET /api/v1/presets: {"presets": [{"name", "description", "valid", "problem"?}]}; a preset that fails its
/// schema is listed with valid = false and the problem.
nlohmann::json presets_index(const std::string& presets_dir);
/// GET /api/v1/scene-engines: {"engines": [{name, version, default, settings: [{name, default, min, max, integer,
/// choices?, unit?, meaning?}]}]}, the registered scene backends in order (the page's engine picker reads it).
nlohmann::json scene_engines_index();

/// GET /api/v1/presets/{name}: the preset document itself.
nlohmann::json preset_document(const std::string& presets_dir, const std::string& name);

/// Runs a preset's expectations: {"name", "passed", "expectations": [{probe, metric, mass_model, value, min,
/// max, passed, note}]}.
nlohmann::json check_preset(const nlohmann::json& preset);

}  // namespace softtune::app
