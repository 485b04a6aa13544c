#pragma once
// The preset search of the stability use case: `softtune stability --preset NAME` and POST
// /api/v1/stability {"preset": NAME}. Each tuned joint's highest stable frequency in Box2D 2.4
// (scene/preset_stability.h), costed and refused (422) over the budget before any world is built.

#include <nlohmann/json.hpp>
#include <string>

namespace softtune::app {

/// Loads preset `name` from `presets_dir` (404 when absent), refuses a modal-tuned one (its joints carry a
/// modal solve, not their own frequency) and one over the budget, then searches it.
/// `engine` holds the request's "engine" and "engine_settings" (read as simulate reads them): the search steps
/// Box2D 2.4's own twin runs, so another engine is a 422 naming `engine`; the answer names the engine.
nlohmann::json run_preset_stability(const std::string& name, const std::string& presets_dir,
                                    const nlohmann::json& engine = nlohmann::json::object());

/// The per-joint table `softtune stability --preset` prints: joint, asked, highest stable (stable side),
/// unstable side, kind, evaluations, margin asked / limit.
std::string preset_limits_table(const nlohmann::json& encoded);

}  // namespace softtune::app
