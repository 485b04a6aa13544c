#pragma once
// matter.js's soft Constraint (stiffness and damping as per-iteration fractions), modelled. Model in
// core/src/engines/matter_js.cpp; the real engine (npm matter-js 0.20.0) runs it in tests/engines/matter_js.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kMatterJsModel;

/// Indices of kMatterJsModel.settings.
enum MatterJsSetting : int {
  kMatterJsConstraintIterations = 0,
  kMatterJsFrictionAir = 1,
  kMatterJsAnchorLeverage = 2,
};

/// matter.js's Common._baseDelta: the step (ms) its fractions are written for.
inline constexpr double kMatterJsBaseDeltaMs = 1000.0 / 60.0;

/// Constraint._warming: the fraction of a pass's constraint impulse carried into the next pass.
inline constexpr double kMatterJsWarming = 0.4;

/// One Engine.update(engine, delta_ms) of one body on one soft Constraint (length > 0, stiffness < 1) to a
/// fixed point, no gravity and no contacts, on the state (u, u_prev, w, w_prev, I_u, I_w) along the
/// constraint: u the body's centre, w = (r x n) angle the anchor's turn, I_u, I_w the carried
/// constraintImpulse; the anchor's stretch is u + w. `leverage` is q = (r x n)^2 inverseInertia /
/// (inverseMass + inverseInertia) (1 - angularStiffness): 0 for an anchor at the centre. Exposed for tests.
Eigen::Matrix<double, 6, 6> matter_js_step_map(double stiffness, double damping, double delta_ms, int iterations,
                                               double friction_air, double leverage);

}  // namespace softtune::engines
