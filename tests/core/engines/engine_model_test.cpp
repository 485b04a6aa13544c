// The shared engine-model pieces against closed forms: the prediction of a step map is the continuous
// oscillator whose poles it has, and the response solver finds parameters a closed form knows.
#include "softtune/engines/engine_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/engines/box2d_v2_4.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

// The exact discrete map of m x'' + c x' + k x = 0 over dt: poles exp(s dt), s = -zeta omega +- i omega_d,
// built as the companion form of z^2 - 2 r cos(theta) z + r^2.
Eigen::MatrixXd exact_map(double omega, double zeta, double dt) {
  const double r = std::exp(-zeta * omega * dt), theta = omega * std::sqrt(1.0 - zeta * zeta) * dt;
  Eigen::MatrixXd a(2, 2);
  a << 0.0, 1.0, -r * r, 2.0 * r * std::cos(theta);
  return a;
}

TEST(PredictFromStepMap, ReadsTheContinuousOscillatorOfExactPoles) {
  const double dt = 1.0 / 60.0;
  for (double hz : {0.5, 3.0, 12.0}) {
    for (double zeta : {0.0, 0.1, 0.7}) {
      const double omega = 2.0 * std::numbers::pi * hz;
      const Prediction p = predict_from_step_map(exact_map(omega, zeta, dt), dt);
      ASSERT_TRUE(p.frequency_hz && p.damping_ratio);
      EXPECT_NEAR(*p.frequency_hz, hz, 1e-9 * hz);
      EXPECT_NEAR(*p.damping_ratio, zeta, 1e-9);
      EXPECT_NEAR(p.spectral_radius, std::exp(-zeta * omega * dt), 1e-12);
      EXPECT_TRUE(p.stable);
    }
  }
}

TEST(PredictFromStepMap, AFastExtraStateLeavesTheDominantPair) {
  // A third state that decays by 0.01 per step (a warm-started impulse, say) does not change the reading.
  const double dt = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 4.0;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 3);
  a.topLeftCorner(2, 2) = exact_map(omega, 0.2, dt);
  a(2, 2) = 0.01;
  a(2, 0) = 0.5;
  const Prediction p = predict_from_step_map(a, dt);
  ASSERT_TRUE(p.frequency_hz);
  EXPECT_NEAR(*p.frequency_hz, 4.0, 1e-9);
  EXPECT_NEAR(*p.damping_ratio, 0.2, 1e-9);
}

TEST(PredictFromStepMap, GrowthAndNonFiniteMapsAreUnstable) {
  Eigen::MatrixXd grow(2, 2);
  grow << 1.1, 0.0, 0.0, 0.5;
  EXPECT_FALSE(predict_from_step_map(grow, 0.01).stable);
  Eigen::MatrixXd bad = Eigen::MatrixXd::Constant(2, 2, std::nan(""));
  const Prediction p = predict_from_step_map(bad, 0.01);
  EXPECT_FALSE(p.stable);
  EXPECT_FALSE(p.frequency_hz);
}

TEST(SolveResponse, FindsTheExactSoftSpringOfImplicitEuler) {
  // Box2D 2.4.1 steps implicit Euler; the (k, c) that make its poles exp(s h) are softtune's exact k', c'
  // (core/exact_softness.h, a closed form), which the solver must find from the standard guess.
  const double m = 2.0, h = 1.0 / 60.0;
  for (double hz : {1.0, 5.0, 10.0, 18.0}) {
    for (double zeta : {0.05, 0.5, 1.0, 2.0}) {
      const double omega = 2.0 * std::numbers::pi * hz;
      const ExactSpring closed = exact_spring(m, omega, zeta, h);
      const SpringConstants guess = spring_constants(m, omega, zeta);
      const ResponseSolve s = solve_response(
          [&](double k, double c) -> std::optional<Prediction> {
            if (!(c + h * k > 0.0)) return std::nullopt;
            return predict_from_step_map(box2d_v2_4_step_map(m, k, c, h), h);
          },
          omega, zeta, guess.stiffness, guess.damping);
      ASSERT_TRUE(s.met) << hz << " Hz, zeta " << zeta;
      EXPECT_NEAR(s.p0, closed.spring.stiffness, 2e-3 * closed.spring.stiffness) << hz << " " << zeta;
      EXPECT_NEAR(s.p1, closed.spring.damping, 2e-3 * std::abs(closed.spring.stiffness) * h + 1e-9)
          << hz << " " << zeta;
    }
  }
}

TEST(SolveResponse, ReportsTheNearestWhenTheTargetCannotBeMet) {
  // An engine that can only damp (zeta >= 0.3 whatever is typed) cannot reach zeta 0.
  const ResponseSolve s = solve_response(
      [](double p0, double p1) -> std::optional<Prediction> {
        Prediction p;
        p.frequency_hz = std::sqrt(p0) / (2.0 * std::numbers::pi);
        p.damping_ratio = 0.3 + std::abs(p1);
        p.spectral_radius = 0.9;
        return p;
      },
      2.0 * std::numbers::pi, 0.0, 1.0, 0.2);
  EXPECT_FALSE(s.met);
  EXPECT_NEAR(s.damping_error, 0.3, 1e-3);
  EXPECT_NEAR(s.frequency_error, 0.0, 1e-3);
}

}  // namespace
}  // namespace softtune::engines
