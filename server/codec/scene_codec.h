#pragma once
// The simulate / presets / check contracts (shared by `softtune simulate`, `softtune check` and
// POST /api/v1/simulate, GET /api/v1/presets[/{name}]): JSON <-> softtune::scene types.
// Field list: docs/scenes.md.

#include <nlohmann/json.hpp>
#include <string>

#include "codec/json_reader.h"
#include "softtune/scene/expectations.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::codec {

/// Largest frame_stride of a simulate request (also in openapi.json's x-softtune-limits).
inline constexpr int kMaxFrameStride = 1000;

/// Decodes a scene (already schema-valid, or not: every field is read strictly) and checks its ranges and
/// references; throws Problem (422) naming the dotted field and the rule.
scene::Scene decode_scene(const nlohmann::json& doc);

/// Encodes a run: name, mass_model, stages, joints (m_eff, k, c), oscillators, probes (requested, measured,
/// error, series), max_constraint_error, finite, left_world, and `frames` when snapshots were recorded.
nlohmann::json encode_scene_result(const scene::Scene& scene, const scene::SceneResult& result);

/// A simulate request: {"preset": NAME} or {"scene": {...}} or a bare scene, plus the options
/// "mass_model" ("effective" | "box2d_reduced"), "frames" (bool) and "frame_stride" (1..1000).
/// Presets come from `presets_dir`; a full scene is validated against `presets_dir`/schema.json too.
nlohmann::json run_simulate(const nlohmann::json& request, const std::string& presets_dir);

/// The scene document a request names: {"preset": NAME}, {"scene": {...}}, or the request itself as a bare
/// scene without its `run_options` keys; validated against presets/schema.json. Marks what it read in `r`.
nlohmann::json requested_scene_document(ObjectReader& r, const nlohmann::json& request, const std::string& presets_dir,
                                        std::initializer_list<const char*> run_options);

/// The optional "mass_model" field ("effective" | "box2d_reduced").
std::optional<scene::MassModel> read_mass_model(ObjectReader& r);
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

}  // namespace softtune::codec
