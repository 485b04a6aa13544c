#pragma once
// The modes use case, shared by `softtune modes` and POST /api/v1/modes: a scene (preset or request) settled in
// Box2D, linearised about its rest state (scene/linearise.h) and its modes reported (core modes.h). A scene with
// `modal_tuning` is solved first: the modes are those of the scene as it runs.

#include <nlohmann/json.hpp>
#include <string>

namespace softtune::app {

/// A modes request: {"preset": NAME} or {"scene": {...}} or a bare scene, plus "mass_model" and "at_s" (s, within
/// [0, world.duration_s]: linearise at that time instead of at rest) and "engine" / "engine_settings" (named in the
/// answer's `engine`; the linearisation is of Box2D 2.4's step, so another engine is a 422 naming `engine`).
nlohmann::json run_modes(const nlohmann::json& request, const std::string& presets_dir);

}  // namespace softtune::app
