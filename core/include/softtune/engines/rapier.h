#pragma once
// Rapier's joint motors (GenericJoint motors: prismatic, revolute and spring joints), modelled. Model in
// core/src/engines/rapier.cpp; the real engine (npm @dimforge/rapier2d-compat, rapier3d-compat 0.21.0) runs
// it in tests/engines/rapier.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kRapierModel;

/// Rapier (f32 in the JS packages) computes dt^2 k + dt c and inverts it with utils::inv, which returns 0 for
/// 0 (motor_model.rs combine_coefficients): at 0 the motor turns into a rigid velocity lock, near 0 the
/// spring vanishes. The model refuses springs whose c + h k is below this fraction of h k.
inline constexpr double kRapierFloatMargin = 1e-4;

/// Indices of kRapierModel.settings.
enum RapierSetting : int {
  kRapierNumSolverIterations = 0,
  kRapierNumInternalPgsIterations = 1,
  kRapierMotorModel = 2,
  kRapierAdditionalSolverIterations = 3,
  kRapierLinearDamping = 4,
};

/// One World::step of dt: `substeps` substeps of dt / substeps, each the soft motor row solved on
/// effective mass m with force-based stiffness k and damping c, then the body's linear damping applied once
/// (v /= 1 + dt damping). The state (x, v) after the step. Exposed for tests.
Eigen::Matrix2d rapier_step_map(double m, double k, double c, double dt, int substeps, double linear_damping);

}  // namespace softtune::engines
