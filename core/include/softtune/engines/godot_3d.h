#pragma once
// Godot 3.2.3's 3-D physics (Debian's godot3-server 3.2.3): one Generic6DOFJoint between a StaticBody and a
// RigidBody, its X linear limit off and its X linear spring on, on Godot 3.2's default Bullet backend (Bullet
// 2.89 as bundled in Godot's thirdparty/) or on GodotPhysics 3-D. Model in core/src/engines/godot_3d.cpp; the
// real engine runs it through godot3-server in tests/engines/godot.

#include <vector>

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kGodot3DModel;

/// Settings, indexed like kGodot3DModel.settings.
enum Godot3DSetting : int {
  kGodot3DPhysicsEngine = 0,     ///< physics/3d/physics_engine: 0 Bullet (DEFAULT), 1 GodotPhysics
  kGodot3DDefaultLinearDamp = 1, ///< physics/3d/default_linear_damp, 1/s, default 0.1
  kGodot3DLinearDamp = 2,        ///< the RigidBody's linear_damp, 1/s; -1 (the default) adds nothing
};

/// The velocity Bullet keeps per step from the body's damping: 1 - h (default_linear_damp + linear_damp), the
/// body's counted only when >= 0, clamped to [0, 1].
double godot_3d_bullet_velocity_kept(const SettingValues& values, double h);

/// One Bullet 2.89 world step of a body of mass m on the joint's X spring of stiffness k and damping c, on
/// (x, v): damping first, then the spring row's impulse -- the sum of spring and damper, except that while
/// the body moves towards the rest point with the damper stronger than the spring the row's limits leave
/// the damper alone -- then x += h v. Piecewise linear, so a trajectory is stepped, not a matrix.
void godot_3d_bullet_step(double m, double k, double c, double h, double kept, double& x, double& v);

/// The most steps a prediction steps the model for its fit.
inline constexpr int kGodot3DMaxFitSteps = 1500;

/// The steps a prediction for the asked omega (rad/s) and zeta fits, at step h: six periods, or six of the
/// slowest time constants when it decays sooner (the motion stays above the fit's floor, kFitFloor, so every
/// prediction of one target reads the same window and the solver sees a smooth response), within
/// [64, kGodot3DMaxFitSteps]. A run in Godot compared with the prediction is fitted over as many steps.
int godot_3d_fit_steps(double omega, double zeta, double h);

/// The stretch after each of `steps` steps from x = 1 at rest (steps + 1 samples). Exposed for tests.
std::vector<double> godot_3d_bullet_trajectory(double m, double k, double c, double h, double kept, int steps);

}  // namespace softtune::engines
