#pragma once
// JSON <-> softtune::scene types: the scene documents of presets and requests, and a run's answer.
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

/// Encodes a run: name, mass_model, engine {name, version, settings}, stages, joints (m_eff, k, c, and `parameters`: what to type into the engine that ran), oscillators, probes (requested, measured,
/// error, series), max_constraint_error, finite, left_world, and `frames` when snapshots were recorded.
nlohmann::json encode_scene_result(const scene::Scene& scene, const scene::SceneResult& result);

/// The optional "mass_model" field ("effective" | "box2d_reduced").
std::optional<scene::MassModel> read_mass_model(ObjectReader& r);

/// An optional boolean field, `fallback` when absent.
bool read_bool(ObjectReader& r, std::string_view key, bool fallback);

/// The designer fields of the tune contract on a scene object (a joint, an oscillator, a mode target), read by
/// the tune codec itself; `with_mode` = false leaves "mode" to the caller (a mode target's "mode" names a motion).
/// Empty when the object carries none of them.
std::optional<TuneRequest> read_designer_fields(ObjectReader& r, const std::string& path, bool with_mode = true);

/// Throws the Problem (422) of a scene's field error.
[[noreturn]] void throw_field_error(const FieldError& e);
}  // namespace softtune::codec
