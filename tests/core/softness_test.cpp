#include "softtune/softness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "softtune/integrators.h"

using namespace softtune;

TEST(Softness, SpringConstantsFromModalParameters) {
  // k = m omega^2, c = 2 m zeta omega (Catto GDC 2011, "3:3:2").
  const SpringConstants s = spring_constants(2.0, 10.0, 0.5);
  EXPECT_DOUBLE_EQ(s.stiffness, 200.0);
  EXPECT_DOUBLE_EQ(s.damping, 20.0);
  const Oscillator o{2.0, s.stiffness, s.damping};
  EXPECT_DOUBLE_EQ(natural_angular_frequency(o), 10.0);
  EXPECT_DOUBLE_EQ(damping_ratio_of(o), 0.5);
}

TEST(Softness, GammaAndBetaAreTheTalksFormulas) {
  const double k = 200, c = 20, h = 0.01;
  const Softness s = softness_from_spring(k, c, h);
  EXPECT_EQ(s.kind, SoftnessKind::soft);
  EXPECT_DOUBLE_EQ(s.gamma, 1.0 / 22.0);
  EXPECT_DOUBLE_EQ(s.beta, 2.0 / 22.0);
  EXPECT_DOUBLE_EQ(impulse_gamma(s.gamma, h), s.gamma / h);
  EXPECT_DOUBLE_EQ(bias_factor(s.beta, h), s.beta / h);
}

TEST(Softness, StiffLimitIsRigid) {
  double previous_gamma = INFINITY;
  for (double k = 1; k <= 1e15; k *= 10) {
    const Softness s = softness_from_spring(k, 5.0, 1.0 / 60);
    EXPECT_LT(s.gamma, previous_gamma);
    previous_gamma = s.gamma;
  }
  const Softness stiff = softness_from_spring(1e15, 5.0, 1.0 / 60);
  EXPECT_LT(stiff.gamma, 1e-13);
  EXPECT_NEAR(stiff.beta, 1.0, 1e-12);
  const Softness rigid = softness_from_spring(std::numeric_limits<double>::infinity(), 5.0, 1.0 / 60);
  EXPECT_EQ(rigid.kind, SoftnessKind::rigid);
  EXPECT_EQ(rigid.gamma, 0.0);
  EXPECT_EQ(rigid.beta, 1.0);
}

TEST(Softness, NoSpringMeansNoConstraintWithoutDividingByZero) {
  const Softness s = softness_from_spring(0.0, 0.0, 1.0 / 60);
  EXPECT_EQ(s.kind, SoftnessKind::no_constraint);
  EXPECT_TRUE(std::isfinite(s.gamma));
  EXPECT_TRUE(std::isfinite(s.beta));
  // A soft step with no constraint is free flight.
  const State next = soft_step({1.0, 2.0}, 1.0, s, 0.5);
  EXPECT_DOUBLE_EQ(next.x, 2.0);
  EXPECT_DOUBLE_EQ(next.v, 2.0);
}

TEST(Softness, NegativeDenominatorIsUnrepresentable) {
  EXPECT_EQ(softness_from_spring(100.0, -10.0, 0.01).kind, SoftnessKind::unrepresentable);
}

TEST(Softness, InverseRoundTrips) {
  for (double k : {1e-3, 1.0, 250.0, 1e6}) {
    for (double c : {0.0, 0.1, 40.0}) {
      for (double h : {1e-4, 1.0 / 60, 0.1}) {
        const Softness s = softness_from_spring(k, c, h);
        const SpringConstants back = spring_from_softness(s.gamma, s.beta, h);
        EXPECT_NEAR(back.stiffness, k, 1e-12 * k) << k << " " << c << " " << h;
        EXPECT_NEAR(back.damping, c, 1e-9 * (c + h * k)) << k << " " << c << " " << h;
      }
    }
  }
}

TEST(Softness, BoxV3FormMatchesGammaBeta) {
  // b2MakeSoft: mass_scale + impulse_scale = 1, bias_rate = beta / h, and the soft effective mass
  // m mass_scale equals 1 / (1/m + gamma/h) (Box2D v3 solver.h against Catto GDC 2011).
  const double m = 3.0, omega = 20.0, zeta = 0.3, h = 1.0 / 240;
  const SoftV3 v3 = soft_v3(omega, zeta, h);
  const SpringConstants sc = spring_constants(m, omega, zeta);
  const Softness s = softness_from_spring(sc.stiffness, sc.damping, h);
  EXPECT_NEAR(v3.mass_scale + v3.impulse_scale, 1.0, 1e-15);
  EXPECT_NEAR(v3.bias_rate, bias_factor(s.beta, h), 1e-12 * v3.bias_rate);
  EXPECT_NEAR(m * v3.mass_scale, 1.0 / (1.0 / m + impulse_gamma(s.gamma, h)), 1e-12 * m);
  const SoftV3 zero = soft_v3(0.0, 0.5, h);
  EXPECT_EQ(zero.bias_rate, 0.0);
  EXPECT_EQ(zero.mass_scale, 1.0);
  EXPECT_EQ(zero.impulse_scale, 0.0);
}
