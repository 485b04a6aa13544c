#pragma once
// MuJoCo linked in process (Debian's libmujoco-dev 2.2.2): the oscillator of one soft equality built from an
// EngineRun alone (the mujoco model's `parameters` or `exact`, and its settings).
//
// The constraint is what a MuJoCo user types for a soft 1-D spring to the world, and the one whose
// efc_diagApprox is the true J M^-1 J' (so solimp's impedance means what the model says):
//   point:          a body on a slide joint, held by a joint equality <joint joint1="x" solref solimp/>
//   rotating_plank: a planar plank (slide x, slide y, hinge z) whose off-centre site is tied to a world site
//                   by a spatial tendon and a tendon equality <tendon tendon1="t" solref solimp/> (a
//                   distance constraint of rest length kMujocoRestLength)
// A connect or weld equality would use body_invweight0 (a body's inverse mass at its centre, averaged over
// three axes) as the approximate diagonal, not the anchor's effective mass; a joint limit only pushes.
// Gravity is off; the model's timestep is the run's dt and each sample is one mj_step.

#include <string>

#include "softtune/engines/engine_run.h"

namespace softtune::engines {

/// MuJoCo 2.2.2; integrator "implicitfast" (MuJoCo 3 only) returns an empty trajectory.
extern const RealEngine kMujocoEngine;

/// The tendon's rest length for the rotating plank (m).
inline constexpr double kMujocoRestLength = 1.0;

/// The MJCF text kMujocoEngine loads for a run (exposed for tests and for the page's MJCF snippet).
std::string mujoco_mjcf(const EngineRun& run);

}  // namespace softtune::engines
