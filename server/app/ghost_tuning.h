#pragma once
// The A/B ghost of a scene preview: the same scene with a second tuning on every tuned joint, simulated
// beside the first and drawn translucent over it (scene_frames.h, add_ghost), so a designer sees how
// tuning B moves against tuning A in one frame.

#include <nlohmann/json.hpp>

#include "softtune/scene/scene.h"

namespace softtune::app {

/// `scene` with every tuned joint's designer fields replaced by those `ghost` gives: `response_frames`
/// or `frequency_hz`, `basis_fps`, `oscillation` or `damping_ratio`, `mode` (the rest of each joint's
/// tuning, its fps, substeps and effective mass, stays the scene's). Throws Problem (422) naming
/// `ghost.<field>` for an unknown field or one out of range, or `ghost` when the scene has no tuned joint.
/// A scene tuned by its modes takes the ghost's request on its mode targets too (and its mode for the solve),
/// so the ghost runs its own modal solve rather than the scene's.
scene::Scene ghost_scene(const scene::Scene& scene, const nlohmann::json& ghost);

}  // namespace softtune::app
