#pragma once
// Godot 3.2.3's 2-D physics (GodotPhysics 2-D, Debian's godot3-server 3.2.3): one DampedSpringJoint2D between
// a StaticBody2D and a RigidBody2D. Model in core/src/engines/godot_2d.cpp; the real engine runs it through
// godot3-server in tests/engines/godot.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kGodot2DModel;

/// Settings, indexed like kGodot2DModel.settings.
enum Godot2DSetting : int {
  kGodot2DLinearDamp = 0,  ///< the body's linear_damp (and angular_damp) in effect, 1/s; -1 means the project's
};

/// Physics2DServerSW::init: iterations = 8, fixed in Godot 3.2 (no setting changes it).
inline constexpr int kGodot2DIterations = 8;

/// The number of solver passes that apply the joint's drag: DampedSpringJoint2DSW::solve subtracts the
/// target velocity it set on the pass before, so every second pass finds no relative velocity and applies
/// nothing: ceil(iterations / 2).
inline constexpr int kGodot2DDragPasses = (kGodot2DIterations + 1) / 2;

/// One Physics2DServer step of h of a body of effective mass m on a DampedSpringJoint2D of stiffness k and
/// damping c, with the body's linear damp (1/s): the state (x, v) after the step. Exposed for tests.
Eigen::Matrix2d godot_2d_step_map(double m, double k, double c, double h, double linear_damp);

}  // namespace softtune::engines
