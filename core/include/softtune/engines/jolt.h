#pragma once
// Jolt Physics' soft constraints (SpringSettings on a DistanceConstraint's limits, a SliderConstraint's or
// SixDOFConstraint's limits and motors), modelled. Model in core/src/engines/jolt.cpp; the real engine
// (npm jolt-physics 1.1.0) runs it in tests/engines/jolt.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kJoltModel;

/// Jolt computes dt (c + dt k) in float and divides by it (SpringPart.h
/// CalculateSpringPropertiesWithStiffnessAndDamping): the model refuses springs whose c + h k is below this
/// fraction of h k, far above float's 6e-8 rounding (exact mode at zeta = 0 exports c' + h k' = 0).
inline constexpr double kJoltFloatMargin = 1e-4;

/// Indices of kJoltModel.settings.
enum JoltSetting : int {
  kJoltCollisionSteps = 0,
  kJoltNumVelocitySteps = 1,
  kJoltNumPositionSteps = 2,
  kJoltSpringMode = 3,
  kJoltLinearDamping = 4,
};

/// One PhysicsSystem::Update(dt, collision_steps) of a body of effective mass m on one soft constraint of
/// stiffness k and damping c (what the engine computes from SpringSettings), with the body's
/// mLinearDamping: the state (x, v) after the update. Exposed for tests.
Eigen::Matrix2d jolt_step_map(double m, double k, double c, double dt, int collision_steps,
                              double linear_damping);

}  // namespace softtune::engines
