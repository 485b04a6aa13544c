#pragma once
// The text a scene's preview frames carry under the caption: what the designer asked against what the Box2D
// run measured. A scene tuned by its modes (modal_tuning) was asked for a motion, not for springs, so its
// legend names the targeted mode with the target's request and its probe's measurement, and the solved groups
// by their k, c; the per-joint "asked" of such a joint would be the solve's equivalent per-spring request
// (7.44 Hz for a 3 Hz heave), which nobody asked for.

#include <string>
#include <vector>

#include "softtune/scene/runner.h"
#include "softtune/scene/scene.h"

namespace softtune::app {

/// The legend of a run. Per modal target: "chassis heave: asked 3.00 Hz ζ 0.50 → measured 3.02, ζ 0.48" (its
/// measuring probe's fit; "(not measured)" without one), then per group "suspension (2 joints): solved k
/// 24842 N/m, c 915 N s/m". Per other tuned joint: what was asked against what its first probe with a fit
/// measured over the run; joints no probe measures grouped by what was asked.
std::vector<std::string> scene_legend(const scene::Scene& scene, const scene::SceneResult& result);

/// The band's settings line: the tuned joints' mode(s) (a modal tuning's own mode), fps and substeps.
std::string scene_settings(const scene::Scene& scene);

}  // namespace softtune::app
