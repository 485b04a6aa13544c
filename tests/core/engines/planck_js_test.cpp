// planck.js's model against the engine's own lines (DistanceJoint.ts initVelocityConstraints: k, d from
// frequencyHz, dampingRatio and the joint's mass; the soft step is implicit Euler): what is typed, and the
// poles of implicit Euler in closed form.
#include "softtune/engines/planck_js.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

using testing::kPi;
using testing::target;

SettingValues planck_settings(int joint, double rotation_share = 0.0) {
  SettingValues v = default_settings(kPlanckJsModel);
  v[kPlanckJsJoint] = joint;
  v[kPlanckJsRotationShare] = rotation_share;
  return v;
}

// Implicit Euler on (m, k, d) over h: (m + h d + h^2 k) z^2 - (2 m + h d) z + m = 0; s = ln(z) / h.
std::pair<double, double> implicit_euler_response(double m, double k, double d, double h) {
  const double a = m + h * d + h * h * k, b = -(2.0 * m + h * d), c = m;
  const std::complex<double> z = (-b + std::sqrt(std::complex<double>(b * b - 4.0 * a * c))) / (2.0 * a);
  const std::complex<double> s = std::log(z) / h;
  return {std::abs(s) / (2.0 * kPi), -s.real() / std::abs(s)};
}

TEST(PlanckJsModel, DefaultsAreTheEngines) {
  const SettingValues d = default_settings(kPlanckJsModel);
  EXPECT_EQ(d[kPlanckJsJoint], 0);                // DistanceJoint
  EXPECT_EQ(d[kPlanckJsVelocityIterations], 8);   // World's default
  EXPECT_EQ(planck_js_joint_mass(2.0, 0, 0.0), 2.0);
  EXPECT_EQ(planck_js_joint_mass(2.0, 2, 0.5), 4.0);  // MouseJoint: the body's mass
}

TEST(PlanckJsModel, TypingTheAskedNumbersGivesImplicitEuler) {
  // Standard mode: k = m omega^2, c = 2 m zeta omega, typed back as the asked frequency and damping ratio;
  // the engine then runs implicit Euler on them. The issue: 10 Hz, 0.1 at 60 fps -> 8.25 Hz, 0.48.
  for (int joint : {0, 1, 2}) {
    for (auto [hz, zeta, fps] : {std::tuple{10.0, 0.1, 60.0}, std::tuple{5.0, 0.1, 30.0}, std::tuple{2.0, 1.0, 120.0}}) {
      const double m = 3.0, omega = 2.0 * kPi * hz, h = 1.0 / fps;
      const Target t = target(hz, zeta, m, h, {m * omega * omega, 2.0 * m * zeta * omega});
      const EngineReport r = kPlanckJsModel.report(t, planck_settings(joint));
      const std::string_view f = joint == 0 ? "DistanceJointDef.frequencyHz" : joint == 1 ? "WheelJointDef.frequencyHz" : "MouseJointDef.frequencyHz";
      const std::string_view z = joint == 0 ? "DistanceJointDef.dampingRatio" : joint == 1 ? "WheelJointDef.dampingRatio" : "MouseJointDef.dampingRatio";
      EXPECT_NEAR(*parameter_value(r.parameters, f), hz, 1e-12);
      EXPECT_NEAR(*parameter_value(r.parameters, z), zeta, 1e-12);
      const auto [pf, pz] = implicit_euler_response(m, m * omega * omega, 2.0 * m * zeta * omega, h);
      EXPECT_NEAR(*r.predicted.frequency_hz, pf, 1e-9 * pf);
      EXPECT_NEAR(*r.predicted.damping_ratio, pz, 1e-9);
      if (hz == 10.0 && fps == 60.0) {
        EXPECT_NEAR(pf, 8.25, 0.01);
        EXPECT_NEAR(pz, 0.484, 0.002);
      }
    }
  }
}

TEST(PlanckJsModel, ExactTypesSofttunesExactSpring) {
  // k' = m_j (2 pi f)^2 and c' = 2 m_j zeta_typed (2 pi f): the typed numbers give back the exact spring,
  // whose implicit-Euler poles are the asked ones.
  const double m = 0.7, h = 1.0 / 60.0;
  for (auto [hz, zeta] : {std::pair{2.0, 0.3}, std::pair{10.0, 0.1}, std::pair{15.0, 1.5}}) {
    const double omega = 2.0 * kPi * hz;
    const ExactSpring e = exact_spring(m, omega, zeta, h);
    const EngineReport r = kPlanckJsModel.report(target(hz, zeta, m, h, e.spring), planck_settings(0));
    ASSERT_TRUE(r.exact);
    const double f = *parameter_value(*r.exact, "DistanceJointDef.frequencyHz");
    const double z = *parameter_value(*r.exact, "DistanceJointDef.dampingRatio");
    const double w = 2.0 * kPi * f;
    EXPECT_NEAR(m * w * w / e.spring.stiffness, 1.0, 1e-12);
    EXPECT_NEAR(2.0 * m * z * w, e.spring.damping, 1e-9 * std::abs(e.spring.damping) + 1e-12);
    if (zeta < 1.0) {
      const auto [pf, pz] = implicit_euler_response(m, m * w * w, 2.0 * m * z * w, h);
      EXPECT_NEAR(pf / hz, 1.0, 1e-9);
      EXPECT_NEAR(pz, zeta, 1e-9);
    }
  }
}

TEST(PlanckJsModel, TheMouseJointTypesWithTheBodysMass) {
  // On the plank (rotationShare 0.5) the mouse joint's mass is 2 m_eff: the same k needs 1/sqrt(2) the
  // frequencyHz a distance joint would type.
  const double m = 1.0, hz = 2.0, omega = 2.0 * kPi * hz, h = 1.0 / 60.0;
  const Target t = target(hz, 0.2, m, h, {m * omega * omega, 2.0 * m * 0.2 * omega});
  const EngineReport mouse = kPlanckJsModel.report(t, planck_settings(2, 0.5));
  EXPECT_NEAR(*parameter_value(mouse.parameters, "MouseJointDef.frequencyHz"), hz / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(*parameter_value(mouse.parameters, "MouseJointDef.dampingRatio"), 0.2 / std::sqrt(2.0), 1e-12);
  for (const Warning& w : mouse.warnings) EXPECT_EQ(w.engine, "planck_js");
}

}  // namespace
}  // namespace softtune::engines
