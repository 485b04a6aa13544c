#pragma once
// The cost of running a scene (request_cost.h), from the decoded scene before Box2D sees it: shared by
// simulate and preview.

#include <string>

#include "app/request_cost.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// Box2D: frames x substeps x bodies body-steps at 0.35 us, plus frames x substeps x joints x (velocity +
/// position iterations) at 11 ns; the solver iterates over joints and contacts, not bodies. Calibrated on
/// bench/scene_price_bench.cpp (bodies apart 0.41-0.65 us a body-step at 8 or 100 iterations; a 100-link
/// chain 0.26 us per link-step at 8 + 3 iterations, 1.25 us at 100 + 3). Contacts are not priced: no count
/// made before the run sees them (a 200-box pile measured 1.3 us a body-step at 8 + 3 iterations, 8 us at
/// 100 + 100; 500 circles on one spot 30x the price); the run-time limit bounds those. Each probe keeps and encodes two numbers a frame (about 150 bytes a frame with its JSON tree);
/// recorded frames (`frames`, every frame_stride-th) about 600 bytes per body and 400 per joint.
/// `prefix` is where the scene sits in the request ("scene.", or "" for a bare scene or a preset).
RequestCost scene_cost(const scene::Scene& scene, const scene::RunOptions& options, const std::string& prefix);

}  // namespace softtune::app
