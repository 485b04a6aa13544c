// planck.js 1.4.2 (npm planck 1.4.2, Box2D 2.3 in TypeScript), read in src/dynamics:
//   joint/DistanceJoint.ts  initVelocityConstraints (m_mass = 1 / (invMass + invI (r x u)^2);
//                           frequencyHz > 0: omega = 2 pi frequencyHz, d = 2 m_mass dampingRatio omega,
//                           k = m_mass omega^2, m_gamma = h (d + h k), m_gamma = m_gamma != 0 ? 1 / m_gamma : 0,
//                           m_bias = C h k m_gamma, m_mass = 1 / (invMass + m_gamma); warm start),
//                           solveVelocityConstraints (impulse = -m_mass (Cdot + m_bias + m_gamma m_impulse)),
//                           solvePositionConstraints (returns at once when frequencyHz > 0)
//   joint/WheelJoint.ts     the spring row along the axis: m_springMass, the same three lines
//   joint/MouseJoint.ts     initVelocityConstraints: mass = m_bodyB.getMass() (the body's, not the anchor's
//                           effective mass), the same gamma and beta, wB *= 0.98 ("Cheat with some damping")
//   Solver.ts               solveWorld: integrate velocities (v /= 1 + h linearDamping), joints' init and
//                           velocity iterations, integrate positions (maxTranslation 2 per step), position
//                           iterations
//   World.ts                defaults: velocityIterations 8, positionIterations 3, warmStarting true
// That is Box2D 2.4.1's step line for line (core/src/engines/box2d_v2_4.cpp models it: one soft joint is
// implicit Euler on (m_eff, k, d), the mouse joint on a turning body a third, real mode), computed in
// doubles. The one difference is what is typed: frequencyHz and dampingRatio, which the joint turns into
// k = m_j (2 pi f)^2 and d = 2 m_j zeta (2 pi f) with its own mass m_j (planck_js_joint_mass). So the report is
// Box2D 2.4.1's, its k and d written as the frequencyHz and dampingRatio that give them: typing the asked
// frequency and damping ratio gives implicit Euler's response, not the asked one (10 Hz, 0.1 at 60 fps:
// 8.25 Hz, 0.48), and `exact` types the ones that do. The body's linearDamping (default 0) is not modelled.
#include "softtune/engines/planck_js.h"

#include <array>
#include <cmath>
#include <numbers>

#include "softtune/engines/box2d_v2_4.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 3> kJointChoices = {"distance", "wheel", "mouse"};
constexpr std::array<SettingSpec, 3> kSettings = {{
    {"joint", 0, 0, 2, true, kJointChoices, "",
     "which joint carries the spring (DistanceJoint, WheelJoint along its axis, MouseJoint)"},
    {"velocityIterations", 8, 1, 1000, true, {}, "", "World.step velocityIterations; one joint converges in the first"},
    {"rotationShare", 0, 0, 0.999, false, {}, "",
     "not a planck field: the share of 1/m_eff that is the body's rotation, invI (r x u)^2 m_eff (0 for a point "
     "or fixedRotation body, 0.5 for the rotating plank); the mouse joint's 0.98 angular damping acts on it "
     "and its mass is the body's, m_eff / (1 - rotationShare)"},
}};

constexpr std::array<std::array<std::string_view, 2>, 3> kFieldNames = {{
    {"DistanceJointDef.frequencyHz", "DistanceJointDef.dampingRatio"},
    {"WheelJointDef.frequencyHz", "WheelJointDef.dampingRatio"},
    {"MouseJointDef.frequencyHz", "MouseJointDef.dampingRatio"},
}};

// Box2D 2.4.1's (k, d) as planck's frequencyHz and dampingRatio for the joint mass m_j: f = sqrt(k / m_j) / 2 pi,
// zeta = d / (2 sqrt(k m_j)); k <= 0 (no spring: rigid) is typed as frequencyHz 0, which planck runs rigid.
Parameters planck_parameters(const Parameters& box2d, int joint, double m_j) {
  const double k = box2d.size() > 0 ? box2d[0].value : 0.0, d = box2d.size() > 1 ? box2d[1].value : 0.0;
  const auto& names = kFieldNames[static_cast<std::size_t>(joint)];
  const bool spring = k > 0.0;
  Parameters out = {{names[0], spring ? std::sqrt(k / m_j) / (2.0 * std::numbers::pi) : 0.0, "Hz"},
                    {names[1], spring ? d / (2.0 * std::sqrt(k * m_j)) : 0.0, ""}};
  if (joint == 2) out.push_back({"MouseJointDef.maxForce", kBox2DV24MouseMaxForce, "N"});
  return out;
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out = kBox2DV24Model.report(t, values);
  out.settings = describe_settings(kPlanckJsModel, values);
  const int joint = static_cast<int>(values[kPlanckJsJoint]);
  const double m_j = planck_js_joint_mass(t.effective_mass, joint, values[kPlanckJsRotationShare]);
  out.parameters = planck_parameters(out.parameters, joint, m_j);
  if (out.exact) out.exact = planck_parameters(*out.exact, joint, m_j);
  for (Warning& w : out.warnings) w.engine = kPlanckJsModel.name;
  return out;
}

}  // namespace

double planck_js_joint_mass(double effective_mass, int joint, double rotation_share) {
  return joint == 2 ? effective_mass / (1.0 - rotation_share) : effective_mass;
}

const EngineModel kPlanckJsModel = {
    "planck_js",
    "planck.js 1.4.2 (npm planck 1.4.2): src/dynamics/joint/DistanceJoint.ts, WheelJoint.ts, MouseJoint.ts "
    "(initVelocityConstraints, solveVelocityConstraints, solvePositionConstraints), src/dynamics/Solver.ts "
    "(solveWorld); the step is Box2D 2.4.1's (box2d_v2_4.cpp)",
    kSettings,
    report,
};

}  // namespace softtune::engines
