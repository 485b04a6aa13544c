#pragma once
// cannon-es 0.20 (npm cannon-es 0.20.0): one body on a Spring (Hooke forces, applied after each step) or on
// a DistanceConstraint (its equation's SPOOK parameters), stepped by World.step. Model in
// core/src/engines/cannon_es.cpp; the real engine runs it under node in tests/engines/cannon_es.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kCannonEsModel;

/// Indices of kCannonEsModel.settings.
enum CannonEsSetting : int {
  kCannonEsJoint = 0,          ///< `spring` (Spring.applyForce on postStep) or `distance` (DistanceConstraint)
  kCannonEsLinearDamping = 1,  ///< Body.linearDamping (and angularDamping), default 0.01
  kCannonEsSpookTimeStep = 2,  ///< the timeStep passed to setSpookParams (s); 0: the world's step
  kCannonEsIterations = 3,     ///< GSSolver.iterations, default 10
};

/// The choices of the joint setting.
enum CannonEsJoint : int { kCannonEsSpring = 0, kCannonEsDistance = 1 };

/// One world.step(dt) of a body of effective mass m on a Spring of stiffness k (N/m) and damping c (N s/m)
/// whose applyForce runs on postStep, with Body.linearDamping `linear_damping`: the state (x, v) after the
/// step. The values are the ones the Spring holds (after its `|| 100` and `|| 1`). Exposed for tests.
Eigen::Matrix2d cannon_es_spring_step_map(double m, double k, double c, double dt, double linear_damping);

/// The same for a DistanceConstraint whose equation had setSpookParams(stiffness, relaxation, spook_dt),
/// the world stepping by dt.
Eigen::Matrix2d cannon_es_spook_step_map(double m, double stiffness, double relaxation, double spook_dt, double dt,
                                         double linear_damping);

}  // namespace softtune::engines
