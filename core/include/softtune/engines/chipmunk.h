#pragma once
// Chipmunk 7 (Debian's libchipmunk-dev 7.0.3, cpFloat double): one cpDampedSpring between a body and a
// static body, stepped by cpSpaceStep. Model in core/src/engines/chipmunk.cpp; the real engine runs it in
// engines/chipmunk and tests/engines/chipmunk.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kChipmunkModel;

/// Settings, indexed like kChipmunkModel.settings.
enum ChipmunkSetting : int {
  kChipmunkIterations = 0,  ///< cpSpaceSetIterations, default 10
  kChipmunkDamping = 1,     ///< cpSpaceSetDamping: the fraction of velocity kept per second, default 1
};

/// One cpSpaceStep(dt) of a body of effective mass m on a cpDampedSpring of stiffness k (N/m) and damping
/// c (N s/m), with the space's damping (fraction kept per second): the state (x, v) after the step.
/// Exposed for tests.
Eigen::Matrix2d chipmunk_step_map(double m, double k, double c, double dt, double space_damping);

}  // namespace softtune::engines
