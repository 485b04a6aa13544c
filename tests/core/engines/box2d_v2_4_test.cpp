// Box2D 2.4.1's model against the talk: one world step with one soft joint is implicit Euler (docs/math.md),
// so its plain export predicts standard softness and its exact parameters are softtune's k', c'.
#include "softtune/engines/box2d_v2_4.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <numbers>

#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"
#include "softtune/exact_softness.h"
#include "softtune/integrators.h"

namespace softtune::engines {
namespace {

using testing::target;

TEST(Box2DV24Model, StepMapIsImplicitEuler) {
  const double m = 3.0, k = 500.0, c = 4.0, h = 1.0 / 60.0;
  const Eigen::Matrix2d a = box2d_v2_4_step_map(m, k, c, h);
  testing::expect_implicit_euler(a, m, k, c, h);
}

TEST(Box2DV24Model, StandardExportPredictsImplicitEulersPoles) {
  // docs/math.md: asked 10 Hz free at 60 fps, standard softness gives 8.49 Hz natural with zeta 0.416.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 10.0;
  const EngineReport r = kBox2DV24Model.report(target(10.0, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                               default_settings(kBox2DV24Model));
  ASSERT_TRUE(r.predicted.frequency_hz);
  EXPECT_NEAR(*r.predicted.frequency_hz, 8.49, 0.01);
  EXPECT_NEAR(*r.predicted.damping_ratio, 0.416, 0.001);
  // Implicit Euler always damps; undamped is reached within the tolerance only by a spring whose
  // damping + h stiffness stays clear of zero (Box2D computes it in float and turns rigid at 0).
  ASSERT_TRUE(r.exact && r.exact_predicted);
  const double k = *parameter_value(*r.exact, "b2DistanceJointDef::stiffness");
  const double d = *parameter_value(*r.exact, "b2DistanceJointDef::damping");
  EXPECT_GE(d + h * k, kBox2DV24FloatMargin * h * k);
  EXPECT_LE(std::abs(*r.exact_predicted->damping_ratio), kExactDampingTolerance);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, 10.0, 10.0 * kExactFrequencyTolerance);
}

TEST(Box2DV24Model, ExactParametersAreTheExactSoftSpring) {
  const double m = 0.5, h = 1.0 / 120.0;
  for (double zeta : {0.1, 0.5, 1.5}) {
    const double omega = 2.0 * std::numbers::pi * 7.0;
    const EngineReport r = kBox2DV24Model.report(target(7.0, zeta, m, h, spring_constants(m, omega, zeta)),
                                                 default_settings(kBox2DV24Model));
    ASSERT_TRUE(r.exact && r.exact_predicted) << zeta;
    const ExactSpring closed = exact_spring(m, omega, zeta, h);
    EXPECT_NEAR((*r.exact)[0].value, closed.spring.stiffness, 2e-3 * closed.spring.stiffness);
    EXPECT_NEAR(*r.exact_predicted->frequency_hz, 7.0, 7e-3);
    EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 5e-3);
  }
}

TEST(Box2DV24Model, ARefusedExportPredictsWhatTheEngineRuns) {
  // Exact mode at zeta = 0 gives d = -h k: InitVelocityConstraints computes m_gamma = h (d + h k) in float.
  // Where that is exactly 0 (h = 1/64, k = 1024: h k = 16 = -d in float) m_gamma = 0 and the joint is rigid.
  const double m = 1.0;
  {
    const double h = 1.0 / 64.0, k = 1024.0;
    testing::expect_refused_and_held(kBox2DV24Model.report(target(5.0, 0.0, m, h, {k, -h * k}), default_settings(kBox2DV24Model)));
  }
  // At h = 1/60 the float sum keeps a few ulp of h k: m_gamma is huge, the soft mass ~ 1 / m_gamma, and the
  // step is symplectic Euler on an undamped spring, cos(omega_d h) = 1 - h^2 k / (2 m).
  {
    const double h = 1.0 / 60.0, k = 1000.0;
    const float sum = static_cast<float>(-h * k) + static_cast<float>(h) * static_cast<float>(k);
    ASSERT_NE(sum, 0.0f);
    const EngineReport r = kBox2DV24Model.report(target(5.0, 0.0, m, h, {k, -h * k}), default_settings(kBox2DV24Model));
    ASSERT_TRUE(r.predicted.frequency_hz && r.predicted.damping_ratio);
    EXPECT_NEAR(*r.predicted.frequency_hz, std::acos(1.0 - h * h * k / (2.0 * m)) / (2.0 * testing::kPi * h), 1e-5);
    EXPECT_NEAR(*r.predicted.damping_ratio, 0.0, 1e-5);
    EXPECT_NEAR(r.predicted.spectral_radius, 1.0, 1e-5);
    EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
  }
}

}  // namespace
}  // namespace softtune::engines

namespace softtune::engines {
namespace {

TEST(Box2DV24Model, MouseJointOnARotatingBody) {
  // Without rotation the mouse joint's map is the distance joint's (implicit Euler) on (x, u_t).
  const double m = 2.0, k = 300.0, d = 3.0, h = 1.0 / 60.0;
  const Eigen::Matrix3d point = box2d_v2_4_mouse_step_map(m, k, d, h, 0.0);
  const Eigen::Matrix2d ie = box2d_v2_4_step_map(m, k, d, h);
  EXPECT_LT((point.topLeftCorner<2, 2>() - ie).norm(), 1e-12);
  // With rotation, the 0.98 multiplies the rotation's share of the anchor velocity before the solve: one
  // step from (0, 0, u_r) with no spring force keeps 0.98 u_r of it in x's velocity... then the soft solve.
  const double a = 0.5, gi = 1.0 / (h * (d + h * k)), soft = 1.0 / (1.0 / m + gi);
  const Eigen::Matrix3d plank = box2d_v2_4_mouse_step_map(m, k, d, h, a);
  const double u = 0.98;                 // Cdot after InitVelocityConstraints for u_r = 1
  const double p = -soft * u;            // the impulse (warm start cancels)
  EXPECT_NEAR(plank(1, 2), (1.0 - a) * p / m, 1e-12);
  EXPECT_NEAR(plank(2, 2), 0.98 + a * p / m, 1e-12);
  EXPECT_NEAR(plank(0, 2), h * (u + p / m), 1e-12);
  // At low frequency the third mode carries much of the stretch: the model warns and gives no exact.
  Target t;
  t.effective_mass = 1.0;
  t.omega = 2.0 * std::numbers::pi * 0.6;
  t.damping_ratio = 0.3;
  t.dt = 1.0 / 240.0;
  t.spring = spring_constants(1.0, t.omega, 0.3);
  const EngineReport r = kBox2DV24Model.report(t, {2, 8, 0.5});
  EXPECT_FALSE(r.exact);
  EXPECT_GT(box2d_v2_4_mouse_third_mode_weight(1.0, t.spring.stiffness, t.spring.damping, t.dt, 0.5),
            kBox2DV24MouseThirdModeLimit);
  EXPECT_EQ((*parameter_value(r.parameters, "b2MouseJointDef::maxForce")), kBox2DV24MouseMaxForce);
}

}  // namespace
}  // namespace softtune::engines
