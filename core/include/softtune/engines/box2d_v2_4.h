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

/// The mouse joint's step on a body a share `rotation_share` of whose inverse effective mass is rotation:
/// state (x, anchor velocity from translation, anchor velocity from rotation); InitVelocityConstraints
/// multiplies the angular velocity by 0.98 each step. Exposed for tests.
Eigen::Matrix3d box2d_v2_4_mouse_step_map(double m, double k, double d, double h, double rotation_share);

/// The weight of that map's third (real, rotation) mode in the stretch after a release from rest at x0 = 1:
/// its residue |v_0i (V^-1)_i0|. Where it exceeds kBox2DV24MouseThirdModeLimit the motion is not second
/// order: the model warns, and gives no `exact`.
double box2d_v2_4_mouse_third_mode_weight(double m, double k, double d, double h, double rotation_share);
inline constexpr double kBox2DV24MouseThirdModeLimit = 0.01;

/// b2MouseJointDef::maxForce the model exports (N): the joint caps its impulse at h maxForce (default 0, which
/// holds nothing), so any cap above the spring's peak force leaves the spring linear; 1e15 N is far above
/// every spring of the grid while h maxForce squared stays finite in float.
inline constexpr double kBox2DV24MouseMaxForce = 1e15;

}  // namespace softtune::engines
