#pragma once
// PhysX 5 (NVIDIA-Omniverse/PhysX 5.6.1): a PxD6Joint linear drive (PxD6JointDrive) as one soft 1-D row, under
// the PGS or the TGS solver. Not installable here: the model follows the published source and its test
// re-runs the solver's loop for one row. Model in core/src/engines/physx.cpp.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kPhysxModel;

/// Settings, indexed like kPhysxModel.settings.
enum PhysxSetting : int {
  kPhysxSolverType = 0,          ///< PxSceneDesc::solverType: 0 ePGS (default), 1 eTGS
  kPhysxPositionIterations = 1,  ///< PxRigidDynamic::setSolverIterationCounts minPositionIters, default 4
  kPhysxVelocityIterations = 2,  ///< minVelocityIters, default 1
  kPhysxDriveType = 3,           ///< 0 force drive, 1 acceleration drive (PxD6JointDriveFlag::eACCELERATION)
};

/// PhysX stores drive stiffness and damping as PxReal (float): a value above this is infinity to it.
inline constexpr double kPhysxFloatMax = 3.4028234663852886e38;

/// The number of implicit-Euler steps one PxScene::simulate(dt) takes on a drive row: 1 under PGS (the
/// row converges in its first pass and velocity iterations leave it there), positionIterations under TGS
/// (each position iteration is a substep of dt / positionIterations; velocity iterations apply no spring
/// impulse).
int physx_substeps(const SettingValues& values);

/// PhysX's step over dt of a drive with stiffness k and damping d (as typed into PxD6JointDrive) on
/// effective mass m, `substeps` implicit-Euler steps of dt / substeps; an acceleration drive is the same on
/// unit mass (pass m = 1). The state (x, v) after one simulate(dt). Exposed for tests.
Eigen::Matrix2d physx_step_map(double m, double k, double d, double dt, int substeps);

}  // namespace softtune::engines
