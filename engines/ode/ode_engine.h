#pragma once
// ODE 0.16 linked in process (libode-dev): one body held by one soft joint row, built from an EngineRun
// alone (the ODE report's `parameters` or `exact` and its `settings`, core/engines/ode.h).
//
// The body sits at the origin, zero gravity, no damping, no auto-disable; the row runs along x:
//   dball   dJointTypeDBall from a world point 1 m along -x to the anchor (dParamERP, dParamCFM); the stretch
//           is the anchors' distance minus 1 m
//   ball    dJointTypeBall at the anchor (dParamERP, dParamCFM, on all three rows); the stretch is the anchor's x
//   slider  dJointTypeSlider along x with dParamLoStop = dParamHiStop = 0 (dParamStopERP, dParamStopCFM);
//           the stretch is dJointGetSliderPosition
// The anchor is the body's centre (RunBody::point) or `offset` from it along y (RunBody::rotating_plank, an
// isotropic inertia so no other row couples to the x row). A slider holds the body's orientation, so a
// plank on a slider does not turn: that run returns an empty trajectory.

#include "softtune/engines/engine_run.h"

namespace softtune::engines {

extern const RealEngine kOdeEngine;

}  // namespace softtune::engines
