#pragma once
// planck.js's soft joints (DistanceJoint, WheelJoint's spring, MouseJoint: frequencyHz and dampingRatio),
// modelled. Model in core/src/engines/planck_js.cpp; the real engine (npm planck 1.4.2) runs it in
// tests/engines/planck_js.

#include "softtune/engines/engine_model.h"

namespace softtune::engines {

extern const EngineModel kPlanckJsModel;

/// Indices of kPlanckJsModel.settings (those of kBox2DV24Model: planck.js runs Box2D's step).
enum PlanckJsSetting : int {
  kPlanckJsJoint = 0,
  kPlanckJsVelocityIterations = 1,
  kPlanckJsRotationShare = 2,
};

/// The mass planck.js turns frequencyHz and dampingRatio into k and d with (kg): the joint's own effective
/// mass for the distance and wheel joints (m_mass, m_springMass), the body's mass for the mouse joint
/// (m_bodyB.getMass(): m_eff / (1 - rotationShare)).
double planck_js_joint_mass(double effective_mass, int joint, double rotation_share);

}  // namespace softtune::engines
