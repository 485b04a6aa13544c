#pragma once
// The camera of every frame of a run, chosen once the whole run is known: fixed, fitted to the action
// over the run, or following a body. Whichever it is, the title band (kCaptionBand) at the top stays free
// of the scene, so the caption and legend never cover a body or an anchor.

#include <vector>

#include "softtune/render/draw_model.h"
#include "softtune/render/view.h"

namespace softtune::render {

/// How far beyond the moving things (a fraction of their box's larger side) static shapes still count
/// for a fit: a 200 m ground counts as the strip of road under the car, a wall beside a spring whole.
inline constexpr double kStaticReach = 0.25;

/// What a fitted camera must show of a run: every moving shape (any role but static), spring, pin,
/// target, trail and anchor of every frame, and the static shapes clipped to the moving box grown by
/// kStaticReach. With nothing moving, everything. Ghosts (Role::ghost, ghost springs, pins and anchors)
/// never count: the camera frames the real run, and a ghost that leaves it gets an arrow at the edge
/// (tessellate.h).
Bounds action_bounds(const std::vector<DrawFrame>& frames);

/// Frames a camera follows, with `bounds_m` of the followed thing in each frame (one per frame).
struct Follow {
  std::vector<Bounds> bounds_m;
  double width_m = 10.0;  ///< m across the image, widened when the followed thing would not fit
};

/// One camera per frame. `fixed` (auto_fit false) is used as is; otherwise a follow with one box per
/// frame tracks the followed box (centre x smoothed over about a quarter of the run's frames, y held at
/// the action's height while that fits) and keeps it whole below the band; otherwise one camera fitted
/// to action_bounds over the run. The band is the first frame's (caption_band, tessellate.h).
std::vector<Camera> run_cameras(const Camera& fixed, const Follow& follow, const std::vector<DrawFrame>& frames,
                                ImageSize size);

/// The image rectangle, in world metres, that a camera shows below the title band (`band` of the height).
Bounds visible_below_band(const Camera& camera, ImageSize size, double band = kCaptionBand);

}  // namespace softtune::render
