#pragma once
// Box2D 2.4.1's soft joints (b2DistanceJoint, b2WheelJoint's spring, b2MouseJoint), modelled.
// Model in core/src/engines/box2d_v2_4.cpp; the real engine runs it in tests/engines.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kBox2DV24Model;

/// Box2D 2.4.1 computes d + h k in float and turns the joint rigid at 0: the model refuses springs whose
/// d + h k is below this fraction of h k, far above float's 6e-8 rounding.
inline constexpr double kBox2DV24FloatMargin = 1e-4;

/// Box2D 2.4.1's step of one soft joint on effective mass m over h, for stiffness k and damping d as typed
/// into the joint def: the state (x, v) after one b2World::Step. Exposed for tests.
Eigen::Matrix2d box2d_v2_4_step_map(double m, double k, double d, double h);

}  // namespace softtune::engines
