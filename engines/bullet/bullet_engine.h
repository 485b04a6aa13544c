#pragma once
// Bullet 3.24 linked in process: one body on a btGeneric6DofSpring2Constraint to a static ground, built from
// an EngineRun alone (the model's `parameters` or `exact`, and its settings; core/engines/bullet.h).
//
// The constraint's x axis carries the soft row: the spring2 route leaves it free and enables its spring
// (enableSpring, setStiffness, setDamping with the limitIfNeeded the parameters say); the erp_cfm route locks
// it and sets setParam(BT_CONSTRAINT_STOP_ERP / STOP_CFM, value, 0). The other linear axes are locked; a
// point body has no inertia, the rotating plank keeps its rotation about z free and the others locked.
// Zero gravity, no deactivation (the decaying motion falls below Bullet's sleeping thresholds), the solver's
// m_numIterations from the settings, and stepSimulation(dt, 0): one call is one internal step of dt (with
// maxSubSteps > 0 Bullet would step its fixedTimeStep, 1/60 by default, and interpolate).

#include "softtune/engines/engine_run.h"

namespace softtune::engines {

extern const RealEngine kBulletEngine;

}  // namespace softtune::engines
