#pragma once
// The cost of a preset search (request_cost.h), from the decoded scene before any Box2D world is built.

#include "app/request_cost.h"
#include "softtune/scene/preset_stability.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// searches x the most twin runs a search can take (scan + bisection) x 2 worlds x one run's steps, each
/// run priced as scene_cost prices a Box2D scene of that length (scene_cost.h's rates: 1 us per body and
/// joint step plus 50 ns per iteration; a 3-body chain measured about 2 us a world-step, so it is
/// conservative). The field blamed is `preset`: its size is what the request chose.
RequestCost preset_stability_cost(const scene::Scene& scene, const scene::PresetLimitSettings& settings);

}  // namespace softtune::app
