#pragma once
// The page's tuning on a preset: "move a slider, see the preset move". A simulate or preview request that
// names a preset or a scene may add {"tuning": {...}} with the designer fields of `softtune tune` (without a
// mass: each joint's own bodies give it) and the world's fps and substeps; every designer-tuned joint and
// oscillator of the scene then takes that tuning in place of its own. The preset's own tuning is what the
// page starts from (it reads the scene's first tuned item), so a link carries only the preset's name and
// the tuning, and the server, not each client, applies it.

#include <nlohmann/json.hpp>

namespace softtune::app {

/// The keys `tuning` may hold: the world's step and the designer fields (docs/api.md, "tuning").
inline constexpr const char* kSceneTuningKeys[] = {"fps", "substeps", "response_frames", "basis_fps", "frequency_hz",
                                                   "oscillation", "damping_ratio", "mode"};

/// Checks `tuning` with the tune codec's own rules (the same bounds as POST /api/v1/tune; a refusal names
/// `tuning.<field>`), then applies it to `scene_doc`: world fps and substeps when given; on every joint and
/// oscillator that carries designer fields, those fields are replaced by the tuning's. Joints take the
/// tuning's mode; an oscillator that names its own mode keeps it (the oscillator preset puts standard
/// and exact side by side). Rigid joints, and oscillators that copy a joint, are left as they are.
void apply_scene_tuning(nlohmann::json& scene_doc, const nlohmann::json& tuning);

}  // namespace softtune::app
