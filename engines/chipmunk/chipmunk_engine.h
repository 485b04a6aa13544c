#pragma once
// Chipmunk 7.0.3 linked in process (libchipmunk-dev): one body on one cpDampedSpring to the space's static
// body, built from an EngineRun alone (the chipmunk report's `parameters` or `exact` and its `settings`,
// core/engines/chipmunk.h).
//
// Zero gravity, no shapes (so no collisions), sleeping off (Chipmunk's default). The spring runs from a
// static anchor 1 m along -x to the body's anchor, rest length 1 m; the stretch is the anchors' distance
// minus 1 m. The body is a point of mass m_eff with an infinite moment (RunBody::point), or the rotating
// plank anchored `offset` from its centre along y (RunBody::rotating_plank), so it turns as it swings.

#include "softtune/engines/engine_run.h"

namespace softtune::engines {

extern const RealEngine kChipmunkEngine;

}  // namespace softtune::engines
