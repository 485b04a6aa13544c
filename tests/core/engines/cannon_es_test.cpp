// cannon-es 0.20.0's model against cannon-es's own equations: a literal scalar re-run of World.internalStep for
// one body on a Spring (applyForce on postStep) and on a DistanceConstraint (setSpookParams, GSSolver's
// passes with their clamp), against the continuous poles exp(s h) for `exact`, and against what issue 33
// measured in the real engine (the textbook 10 Hz / 0.5 at 60 fps: a pole that flips sign every step).
#include "softtune/engines/cannon_es.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"

namespace softtune::engines {
namespace {

using testing::target;

struct CannonBody {
  double x, v, f;  // stretch, its rate, the force left by the last postStep
};

// World.internalStep (solver first, then v *= pow(1 - linearDamping, dt), Body.integrate: v += h f / m,
// x += h v, clearForces, then postStep's Spring.applyForce: f = -k x - d v), for the Spring as constructed
// (stiffness || 100, damping || 1).
CannonBody cannon_spring_step(CannonBody b, double m, double k, double c, double h, double linear_damping) {
  const double k_held = k == 0.0 ? 100.0 : k, c_held = c == 0.0 ? 1.0 : c;
  b.v *= std::pow(1.0 - linear_damping, h);
  b.v += h * b.f / m;
  b.x += h * b.v;
  b.f = -k_held * b.x - c_held * b.v;
  return b;
}

// The same with a DistanceConstraint: setSpookParams(k, d, bake), GSSolver.solve's `iterations` passes of
// deltalambda = invC (B - GWlambda - eps lambda) clamped to +-1e6, velocity += vlambda, then the damping
// and the integration (no force).
CannonBody cannon_spook_step(CannonBody b, double m, double k, double d, double bake, double h, double linear_damping,
                             int iterations) {
  const double a = 4.0 / (bake * (1.0 + 4.0 * d)), bb = 4.0 * d / (1.0 + 4.0 * d);
  const double eps = 4.0 / (bake * bake * k * (1.0 + 4.0 * d));
  const double rhs = -b.x * a - b.v * bb, inv_c = 1.0 / (1.0 / m + eps);
  double lambda = 0.0, vlambda = 0.0;
  for (int i = 0; i < iterations; ++i) {
    double delta = inv_c * (rhs - vlambda - eps * lambda);
    if (lambda + delta < -1e6) delta = -1e6 - lambda;
    if (lambda + delta > 1e6) delta = 1e6 - lambda;
    lambda += delta;
    vlambda += delta / m;
    if (delta * delta < 1e-14) break;  // GSSolver.tolerance 1e-7, squared
  }
  b.v += vlambda;
  b.v *= std::pow(1.0 - linear_damping, h);
  b.x += h * b.v;
  return b;
}

SettingValues cannon_settings(int joint, double linear_damping, double bake = 0.0) {
  SettingValues v = default_settings(kCannonEsModel);
  v[kCannonEsJoint] = joint;
  v[kCannonEsLinearDamping] = linear_damping;
  v[kCannonEsSpookTimeStep] = bake;
  return v;
}

TEST(CannonEsModel, SpringMapIsWorldStepWithApplyForceOnPostStep) {
  const double m = 0.7, h = 1.0 / 60.0;
  for (double ld : {0.0, 0.01, 0.5}) {
    for (double c : {0.0, 1.5, 40.0}) {
      const Eigen::Matrix2d a = cannon_es_spring_step_map(m, 300.0, c == 0.0 ? 1.0 : c, h, ld);
      for (CannonBody b0 : {CannonBody{1.0, 0.0, 0}, CannonBody{0.0, 1.0, 0}, CannonBody{0.3, -2.0, 0}}) {
        b0.f = -300.0 * b0.x - (c == 0.0 ? 1.0 : c) * b0.v;  // the postStep before
        const CannonBody b1 = cannon_spring_step(b0, m, 300.0, c, h, ld);
        EXPECT_NEAR(a(0, 0) * b0.x + a(0, 1) * b0.v, b1.x, 1e-12);
        EXPECT_NEAR(a(1, 0) * b0.x + a(1, 1) * b0.v, b1.v, 1e-12);
      }
    }
  }
}

TEST(CannonEsModel, SpookMapIsGsSolverOnOneEquationAtEveryIterationCount) {
  const double m = 2.5, h = 1.0 / 120.0;
  for (int iterations : {1, 2, 10}) {
    for (double bake : {1.0 / 60.0, 1.0 / 120.0}) {
      for (double d : {0.0, 0.5, 4.0}) {
        const Eigen::Matrix2d a = cannon_es_spook_step_map(m, 5000.0, d, bake, h, 0.01);
        for (CannonBody b0 : {CannonBody{0.01, 0.0, 0}, CannonBody{0.0, 0.1, 0}, CannonBody{0.003, -0.2, 0}}) {
          const CannonBody b1 = cannon_spook_step(b0, m, 5000.0, d, bake, h, 0.01, iterations);
          EXPECT_NEAR(a(0, 0) * b0.x + a(0, 1) * b0.v, b1.x, 1e-12);
          EXPECT_NEAR(a(1, 0) * b0.x + a(1, 1) * b0.v, b1.v, 1e-12);
        }
      }
    }
  }
}

TEST(CannonEsModel, TextbookSpringAt10HzHalfDampedFlipsSignEveryStep) {
  // Issue 33, measured in cannon-es at 60 fps: k = m omega^2, c = 2 m zeta omega for 10 Hz / 0.5 gives a pole
  // that flips sign every step: det = l - h c / m = 0.99983 - 1.047 < 0, so one pole is real and negative.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * testing::kPi * 10.0;
  const EngineReport r = kCannonEsModel.report(target(10.0, 0.5, m, h, spring_constants(m, omega, 0.5)),
                                               default_settings(kCannonEsModel));
  std::complex<double> z1, z2;
  eigenvalues_2x2(cannon_es_spring_step_map(m, m * omega * omega, m * omega, h, 0.01), z1, z2);
  EXPECT_LT((z1 * z2).real(), 0.0);
  EXPECT_TRUE(std::min(z1.real(), z2.real()) < 0.0 && std::abs(z1.imag()) < 1e-12);
  EXPECT_EQ(r.parameters[1].value, m * omega);
  ASSERT_TRUE(r.exact);
  EXPECT_TRUE(meets_response(*r.exact_predicted, omega, 0.5));
}

// The continuous poles exp(s h) of (omega, zeta), under-damped.
void expect_poles_of(const Eigen::Matrix2d& a, double omega, double zeta, double h) {
  std::complex<double> z1, z2;
  eigenvalues_2x2(a, z1, z2);
  const std::complex<double> s(-zeta * omega, omega * std::sqrt(1.0 - zeta * zeta));
  const std::complex<double> want = std::exp(s * h);
  const std::complex<double> got = z1.imag() > 0.0 ? z1 : z2;
  EXPECT_NEAR(got.real(), want.real(), 1e-10);
  EXPECT_NEAR(got.imag(), want.imag(), 1e-10);
}

TEST(CannonEsModel, ExactPlacesTheContinuousPolesForBothJoints) {
  for (double fps : {30.0, 60.0, 120.0}) {
    for (double hz : {0.5, 2.0, 8.0}) {
      for (double zeta : {0.0, 0.1, 0.7}) {
        const double m = 3.0, h = 1.0 / fps, omega = 2.0 * testing::kPi * hz;
        const Target t = target(hz, zeta, m, h, spring_constants(m, omega, zeta));
        for (double bake : {0.0, 1.0 / 60.0}) {
          for (int joint : {kCannonEsSpring, kCannonEsDistance}) {
            const EngineReport r = kCannonEsModel.report(t, cannon_settings(joint, 0.01, bake));
            if (!r.exact && joint == kCannonEsDistance && hz / fps > 0.25) {
              // SPOOK's stiffest spring (eps -> 0) cannot place such fast, damped poles: said, not guessed.
              ASSERT_FALSE(r.warnings.empty());
              EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
              continue;
            }
            ASSERT_TRUE(r.exact) << fps << " " << hz << " " << zeta << " joint " << joint << " bake " << bake;
            const double p0 = (*r.exact)[0].value, p1 = (*r.exact)[1].value;
            EXPECT_NE(p1, 0.0);  // a Spring damping 0 would become 1
            const Eigen::Matrix2d a = joint == kCannonEsSpring
                                          ? cannon_es_spring_step_map(m, p0, p1, h, 0.01)
                                          : cannon_es_spook_step_map(m, p0, p1, bake > 0.0 ? bake : h, h, 0.01);
            expect_poles_of(a, omega, zeta, h);
          }
        }
      }
    }
  }
}

TEST(CannonEsModel, ZeroDampingTypedIsPredictedAsDampingOneAndRefused) {
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * testing::kPi * 2.0;
  const EngineReport r = kCannonEsModel.report(target(2.0, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                               cannon_settings(kCannonEsSpring, 0.0));
  EXPECT_EQ(r.parameters[1].value, 0.0);
  // Damping 1 N s/m on 1 kg: det = 1 - h, so zeta = -ln(1 - h) / (2 omega_n h) for the map's poles.
  std::complex<double> z1, z2;
  eigenvalues_2x2(cannon_es_spring_step_map(m, m * omega * omega, 1.0, h, 0.0), z1, z2);
  ASSERT_TRUE(r.predicted.damping_ratio);
  EXPECT_NEAR(std::abs(z1 * z2), 1.0 - h, 1e-12);
  EXPECT_GT(*r.predicted.damping_ratio, 0.03);
  bool refused = false;
  for (const Warning& w : r.warnings) refused = refused || w.code == WarningCode::engine_refuses;
  EXPECT_TRUE(refused);
}

TEST(CannonEsModel, SpookBakedAt60FpsRunsFasterAt120Fps) {
  // The same setSpookParams numbers baked with 1 / 60: stepping at 1 / 120 the stiffness term a g acts twice
  // as often on half the step, and the frequency rises (issue 33 measured 1.98 Hz -> 2.73 Hz in cannon-es).
  const double m = 1.0, omega = 2.0 * testing::kPi * 2.0;
  const Target t60 = target(2.0, 0.1, m, 1.0 / 60.0, spring_constants(m, omega, 0.1));
  Target t120 = t60;
  t120.dt = 1.0 / 120.0;
  const EngineReport r60 = kCannonEsModel.report(t60, cannon_settings(kCannonEsDistance, 0.01, 1.0 / 60.0));
  const EngineReport r120 = kCannonEsModel.report(t120, cannon_settings(kCannonEsDistance, 0.01, 1.0 / 60.0));
  ASSERT_TRUE(r60.predicted.frequency_hz && r120.predicted.frequency_hz);
  EXPECT_GT(*r120.predicted.frequency_hz / *r60.predicted.frequency_hz, 1.3);
  // And exact at 120 fps with the 1 / 60 bake still places the poles.
  ASSERT_TRUE(r120.exact);
  EXPECT_TRUE(meets_response(*r120.exact_predicted, omega, 0.1));
}

TEST(CannonEsModel, SlowUndampedSpookGivesRelaxationZeroAsTheNearestLegal) {
  // 0.15 Hz, zeta 0 at 30 fps: cancelling linearDamping 0.01 (zeta 0.0053 alone) needs 1 + 4 relaxation < 0.
  // The nearest legal is relaxation 0, its predicted damping ratio linearDamping's and the step's own.
  const double m = 1e-3, h = 1.0 / 30.0, omega = 2.0 * testing::kPi * 0.15;
  const EngineReport r = kCannonEsModel.report(target(0.15, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                               cannon_settings(kCannonEsDistance, 0.01));
  ASSERT_TRUE(r.exact);
  EXPECT_EQ((*r.exact)[1].value, 0.0);
  const double body_zeta = -std::log(0.99) / (2.0 * omega);  // pow(0.99, h) per step: rate -ln(0.99) / 2
  EXPECT_NEAR(*r.exact_predicted->damping_ratio, body_zeta, 2e-3);
  EXPECT_TRUE(within_nearest(*r.exact_predicted, omega, 0.0));
  EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
}

}  // namespace
}  // namespace softtune::engines
