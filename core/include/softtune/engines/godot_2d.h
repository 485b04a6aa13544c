#pragma once
// Godot 3.2.3's 2-D physics (GodotPhysics 2-D, Debian's godot3-server 3.2.3): one DampedSpringJoint2D between
// a StaticBody2D and a RigidBody2D, or one PinJoint2D with softness and bias pinning a RigidBody2D. Model in core/src/engines/godot_2d.cpp; the real engine runs it through
// godot3-server in tests/engines/godot.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kGodot2DModel;

/// Settings, indexed like kGodot2DModel.settings.
enum Godot2DSetting : int {
  kGodot2DLinearDamp = 0,  ///< the body's linear_damp (and angular_damp) in effect, 1/s; -1 means the project's
  kGodot2DJoint = 1,       ///< 0: DampedSpringJoint2D, 1: PinJoint2D (softness, bias)
};

/// Space2DSW's constraint_bias, the SPACE_PARAM_CONSTRAINT_DEFAULT_BIAS a joint's bias of 0 stands for.
inline constexpr double kGodot2DDefaultBias = 0.2;

/// Physics2DServerSW::init: iterations = 8, fixed in Godot 3.2 (no setting changes it).
inline constexpr int kGodot2DIterations = 8;

/// The number of solver passes that apply the joint's drag: DampedSpringJoint2DSW::solve subtracts the
/// target velocity it set on the pass before, so every second pass finds no relative velocity and applies
/// nothing: ceil(iterations / 2).
inline constexpr int kGodot2DDragPasses = (kGodot2DIterations + 1) / 2;

/// One Physics2DServer step of h of a body of effective mass m on a DampedSpringJoint2D of stiffness k and
/// damping c, with the body's linear damp (1/s): the state (x, v) after the step. Exposed for tests.
Eigen::Matrix2d godot_2d_step_map(double m, double k, double c, double h, double linear_damp);

/// The same for a PinJoint2D of softness s (1/kg) and bias b: setup's warm start, PinJoint2DSW::solve's first
/// pass reaching v + b x / h - s P = 0 exactly (later passes add nothing), so the step is Catto's soft
/// constraint (gamma = s, beta = b) after the body's damping. Exposed for tests.
Eigen::Matrix2d godot_2d_pin_step_map(double m, double softness, double bias, double h, double linear_damp);

}  // namespace softtune::engines
