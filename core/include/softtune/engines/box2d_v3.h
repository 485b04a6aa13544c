#pragma once
// Box2D v3's soft distance joint (b2DistanceJointDef::enableSpring, ::hertz, ::dampingRatio), modelled from
// its published source (github erincatto/box2d HEAD; Box2D v3 is not installable here). Model in
// core/src/engines/box2d_v3.cpp; tests/core/engines/box2d_v3_test.cpp holds it against a literal
// re-implementation of the v3 solver loop and against the numbers issue 15 measured in the real engine.

#include <optional>

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kBox2DV3Model;

/// b2MakeSoft(hertz, zeta, h) divides by a1 = 2 zeta + h omega (solver.h); the model refuses springs whose
/// a1 is below this fraction of h omega (float cancellation in 2 zeta + h omega stays below 6e-5).
inline constexpr double kBox2DV3FloatMargin = 1e-3;

/// b2Softness (solver.h), computed in double.
struct Box2DV3Softness {
  double bias_rate = 0.0;      ///< 1/s, omega / (2 zeta + h omega)
  double mass_scale = 0.0;     ///< h omega a1 / (1 + h omega a1)
  double impulse_scale = 0.0;  ///< 1 / (1 + h omega a1); mass_scale + impulse_scale = 1
};
Box2DV3Softness box2d_v3_make_soft(double hertz, double zeta, double h);

/// One substep (b2SolverStage_IntegrateVelocities .. b2SolverStage_Relax) of one body of effective mass m
/// on one spring joint, as a map of (stretch x m, velocity v m/s, accumulated impulse joint->impulse N s).
/// Its impulse column is zero: the solve stage cancels the warm start exactly for a single constraint
/// (mass_scale + impulse_scale = 1), so the carried impulse never reaches x or v. Exposed for tests.
Eigen::Matrix3d box2d_v3_substep_map(double m, double hertz, double zeta, double h);

/// One b2World_Step(dt, substeps): the product of the substep maps over h = dt / substeps, after
/// b2PrepareDistanceJoint (which zeroes the impulse when warm starting is off). Exposed for tests.
Eigen::Matrix3d box2d_v3_step_map(double m, double hertz, double zeta, double dt, int substeps,
                                  bool warm_starting);

/// (hertz, dampingRatio) whose substep poles are exp(s h) for s of (omega, zeta): the closed form
/// hertz = W / (2 pi h), dampingRatio = (B - W^2) / (2 W), W^2 = A P (1 + B), from softtune's exact
/// implicit-Euler spring at h (A = k' h^2 / m, B = c' h / m, P = exp(-2 zeta omega h)). Empty when the
/// substep cannot reach it: B must exceed kBox2DV3FloatMargin W^2 (c' > 0: the relax stage's damping
/// is more than the request's), and the poles must lie below Nyquist.
struct Box2DV3Spring {
  double hertz = 0.0;
  double damping_ratio = 0.0;
};
std::optional<Box2DV3Spring> box2d_v3_exact_spring(double omega, double zeta, double h);

/// The least damping ratio a Box2D v3 substep h shows at natural angular frequency omega (its reachable
/// boundary, 2 dampingRatio + h omega -> 0): the substep pole cos(phi) exp(i phi) with |ln z| = omega h.
/// About omega h / 2 for small omega h.
double box2d_v3_min_damping_ratio(double omega, double h);

}  // namespace softtune::engines
