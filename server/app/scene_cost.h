#pragma once
// The cost of running a scene (request_cost.h), from the decoded scene before Box2D sees it: shared by
// simulate and preview.

#include <string>

#include "app/request_cost.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// Box2D: frames x substeps x (bodies + joints) body-steps at 1 us plus 50 ns per velocity and position
/// iteration (a 200-box pile measured 1.3 us at 8 + 3 iterations, 8 us at 100 + 100; 500 boxes 1.5 us). Each probe keeps and encodes two numbers a frame (about 150 bytes a frame with its JSON tree);
/// recorded frames (`frames`, every frame_stride-th) about 600 bytes per body and 400 per joint.
/// `prefix` is where the scene sits in the request ("scene.", or "" for a bare scene or a preset).
RequestCost scene_cost(const scene::Scene& scene, const scene::RunOptions& options, const std::string& prefix);

}  // namespace softtune::app
