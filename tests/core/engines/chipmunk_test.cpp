// Chipmunk 7.0.3's model against Chipmunk's own equations: a literal scalar re-run of cpSpaceStep for one
// body on one cpDampedSpring (position first, preStep's spring impulse, the space damping, then every
// solver pass of applyImpulse with its target_vrn), and against closed forms: the numbers issue 33 measured
// in the real engine for the textbook k = m omega^2, c = 2 m zeta omega, and exact's poles at exp(s h).
#include "softtune/engines/chipmunk.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

using testing::target;

struct Body {
  double x, v;
};

// cpSpaceStep (cpSpaceStep.c) for one body of mass m on a cpDampedSpring to a static anchor, rest length 0
// along the stretch: cpBodyUpdatePosition, cpDampedSpring preStep (spring impulse (rest - dist) k dt,
// v_coef = 1 - exp(-damping dt k_scalar)), cpBodyUpdateVelocity (v *= cpfpow(damping, dt)), then
// `iterations` passes of applyImpulse.
Body cp_space_step(Body b, double m, double k, double c, double dt, double space_damping, int iterations) {
  b.x += b.v * dt;
  const double n_mass = m;  // 1 / k_scalar for a lone body on the axis
  double target_vrn = 0.0;
  const double v_coef = 1.0 - std::exp(-c * dt / n_mass);
  b.v += (-b.x * k) * dt / m;
  b.v *= std::pow(space_damping, dt);
  for (int i = 0; i < iterations; ++i) {
    const double vrn = b.v;
    const double v_damp = (target_vrn - vrn) * v_coef;
    target_vrn = vrn + v_damp;
    b.v += v_damp * n_mass / m;
  }
  return b;
}

SettingValues with(double iterations, double damping) {
  SettingValues v = default_settings(kChipmunkModel);
  v[kChipmunkIterations] = iterations;
  v[kChipmunkDamping] = damping;
  return v;
}

TEST(ChipmunkModel, StepMapIsCpSpaceStepOnOneDampedSpring) {
  const double m = 0.7, dt = 1.0 / 60.0;
  for (int iterations : {1, 2, 10}) {
    for (double space_damping : {1.0, 0.9, 0.2}) {
      for (double c : {0.0, 1.5, 40.0}) {
        const double k = 300.0;
        const Eigen::Matrix2d a = chipmunk_step_map(m, k, c, dt, space_damping);
        for (Body b0 : {Body{1.0, 0.0}, Body{0.0, 1.0}, Body{0.3, -2.0}}) {
          const Body b1 = cp_space_step(b0, m, k, c, dt, space_damping, iterations);
          EXPECT_NEAR(a(0, 0) * b0.x + a(0, 1) * b0.v, b1.x, 1e-12);
          EXPECT_NEAR(a(1, 0) * b0.x + a(1, 1) * b0.v, b1.v, 1e-12);
        }
      }
    }
  }
}

TEST(ChipmunkModel, TextbookSpringGivesWhatIssue33MeasuredInChipmunk) {
  // Measured in Chipmunk 7 at 60 fps with k = m omega^2, c = 2 m zeta omega: 2 Hz / 0.1 -> 1.983 Hz /
  // 0.101; 10 Hz / 0.5 -> 7.73 Hz / 0.647.
  const double m = 1.0, h = 1.0 / 60.0;
  struct Case {
    double hz, zeta, measured_hz, measured_zeta;
  };
  for (const Case& c : {Case{2.0, 0.1, 1.983, 0.101}, Case{10.0, 0.5, 7.73, 0.647}}) {
    const double omega = 2.0 * std::numbers::pi * c.hz;
    const EngineReport r = kChipmunkModel.report(target(c.hz, c.zeta, m, h, spring_constants(m, omega, c.zeta)),
                                                 default_settings(kChipmunkModel));
    ASSERT_TRUE(r.predicted.frequency_hz) << c.hz;
    EXPECT_NEAR(*r.predicted.frequency_hz, c.measured_hz, 0.006 * c.measured_hz) << c.hz;
    EXPECT_NEAR(*r.predicted.damping_ratio, c.measured_zeta, 0.003) << c.hz;
    EXPECT_DOUBLE_EQ(*parameter_value(r.parameters, "cpDampedSpringSetStiffness"), m * omega * omega);
  }
}

TEST(ChipmunkModel, DetAndTraceAreTheDragAndTheExplicitSpring) {
  // det = d e, trace = 1 + d e (1 - h^2 k / m), d = damping^h, e = exp(-c h / m).
  const double m = 2.0, k = 800.0, c = 3.0, h = 1.0 / 90.0, damping = 0.5;
  const Eigen::Matrix2d a = chipmunk_step_map(m, k, c, h, damping);
  const double kept = std::pow(damping, h) * std::exp(-c * h / m);
  EXPECT_NEAR(a.determinant(), kept, 1e-14);
  EXPECT_NEAR(a.trace(), 1.0 + kept * (1.0 - h * h * k / m), 1e-14);
}

TEST(ChipmunkModel, ExactPutsThePolesAtExpSh) {
  const double m = 0.05, h = 1.0 / 120.0;
  for (double space_damping : {1.0, 0.8}) {
    for (double hz : {1.0, 12.0, 36.0}) {
      for (double zeta : {0.0, 0.3, 1.0, 2.0}) {
        const double omega = 2.0 * std::numbers::pi * hz;
        const ExactSpring closed = exact_spring(m, omega, zeta, h);
        const EngineReport r = kChipmunkModel.report(target(hz, zeta, m, h, closed.spring), with(10, space_damping));
        ASSERT_TRUE(r.exact && r.exact_predicted) << hz << " " << zeta;
        const Eigen::Matrix2d a = chipmunk_step_map(m, (*r.exact)[0].value, (*r.exact)[1].value, h, space_damping);
        // The continuous poles: P = exp(-2 zeta omega h); S = z1 + z2.
        const double e = std::exp(-zeta * omega * h);
        const double s = zeta < 1.0   ? 2.0 * e * std::cos(omega * std::sqrt(1.0 - zeta * zeta) * h)
                         : zeta > 1.0 ? 2.0 * e * std::cosh(omega * std::sqrt(zeta * zeta - 1.0) * h)
                                      : 2.0 * e;
        EXPECT_NEAR(a.determinant(), e * e, 1e-12) << hz << " " << zeta;
        EXPECT_NEAR(a.trace(), s, 1e-12) << hz << " " << zeta;
        EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-6 * hz);
        EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 1e-6);
        // Without space damping the drag is the continuous c = 2 m zeta omega; with it, m ln(damping) less.
        EXPECT_NEAR((*r.exact)[1].value, 2.0 * m * zeta * omega + m * std::log(space_damping), 1e-12);
      }
    }
  }
}

TEST(ChipmunkModel, IterationsChangeNothingForOneSpring) {
  const double m = 3.0, h = 1.0 / 60.0, hz = 5.0, zeta = 0.4, omega = 2.0 * std::numbers::pi * hz;
  const Target t = target(hz, zeta, m, h, spring_constants(m, omega, zeta));
  const EngineReport one = kChipmunkModel.report(t, with(1, 1));
  const EngineReport many = kChipmunkModel.report(t, with(1000, 1));
  EXPECT_EQ(*one.predicted.frequency_hz, *many.predicted.frequency_hz);
  EXPECT_EQ(*one.predicted.damping_ratio, *many.predicted.damping_ratio);
}

TEST(ChipmunkModel, AboveNyquistExactIsNullWithAWarning) {
  const double m = 1.0, h = 1.0 / 60.0, hz = 40.0, omega = 2.0 * std::numbers::pi * hz;
  const EngineReport r =
      kChipmunkModel.report(target(hz, 0.1, m, h, spring_constants(m, omega, 0.1)), default_settings(kChipmunkModel));
  EXPECT_FALSE(r.exact);
  bool warned = false;
  for (const Warning& w : r.warnings) warned |= w.code == WarningCode::engine_inexact && w.engine == "chipmunk";
  EXPECT_TRUE(warned);
}

TEST(ChipmunkModel, ZeroStiffnessIsRefused) {
  const EngineReport r = kChipmunkModel.report(target(0.0, 0.0, 1.0, 1.0 / 60.0, SpringConstants{0.0, 1.0}),
                                               default_settings(kChipmunkModel));
  EXPECT_TRUE(r.parameters.empty());
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
}

}  // namespace
}  // namespace softtune::engines
