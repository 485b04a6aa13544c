#include "softtune/exact_softness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "softtune/discrete_analysis.h"

using namespace softtune;
using cd = std::complex<double>;

namespace {

// Continuous poles s = -zeta omega +- omega sqrt(zeta^2 - 1), mapped by z = exp(s h).
void continuous_poles(double omega, double zeta, double h, cd& z1, cd& z2) {
  const cd root = std::sqrt(cd(zeta * zeta - 1.0, 0.0));
  z1 = std::exp((-zeta * omega + omega * root) * h);
  z2 = std::exp((-zeta * omega - omega * root) * h);
}

// Roots of implicit Euler's characteristic polynomial (m + c h + k h^2) z^2 - (2m + c h) z + m = 0 (docs/math.md, "Exact softness").
void implicit_euler_poles(double m, double k, double c, double h, cd& z1, cd& z2) {
  const double a = m + c * h + k * h * h, b = -(2.0 * m + c * h);
  const cd disc = std::sqrt(cd(b * b - 4.0 * a * m, 0.0));
  z1 = (-b + disc) / (2.0 * a);
  z2 = (-b - disc) / (2.0 * a);
}

double match_error(cd a1, cd a2, cd b1, cd b2) {
  return std::min(std::max(std::abs(a1 - b1), std::abs(a2 - b2)), std::max(std::abs(a1 - b2), std::abs(a2 - b1)));
}

}  // namespace

TEST(ExactSoftness, PolesMatchTheContinuousOscillatorOverTheGrid) {
  const double m = 2.5, fps = 60.0, h = 1.0 / fps;
  int checked = 0;
  for (double ratio = 0.005; ratio <= 0.45 + 1e-12; ratio += 0.005) {  // f / fps
    for (double zeta = 0.0; zeta <= 2.0 + 1e-12; zeta += 0.05) {
      const double omega = 2.0 * std::numbers::pi * ratio * fps;
      if (omega * std::sqrt(std::max(0.0, 1.0 - zeta * zeta)) * h > std::numbers::pi) continue;  // above Nyquist
      const ExactSpring e = exact_spring(m, omega, zeta, h);
      ASSERT_FALSE(e.clamped_to_nyquist);
      cd want1, want2, got1, got2;
      continuous_poles(omega, zeta, h, want1, want2);
      implicit_euler_poles(m, e.spring.stiffness, e.spring.damping, h, got1, got2);
      // Sum and product are well conditioned everywhere, also at the double pole of critical damping.
      EXPECT_NEAR(std::abs((got1 + got2) - (want1 + want2)), 0.0, 1e-9) << ratio << " " << zeta;
      EXPECT_NEAR(std::abs(got1 * got2 - want1 * want2), 0.0, 1e-9) << ratio << " " << zeta;
      if (std::abs(zeta - 1.0) > 0.04) {
        EXPECT_LT(match_error(got1, got2, want1, want2), 1e-9) << ratio << " " << zeta;
      }
      if (zeta > 0.0) {
        EXPECT_GT(e.spring.damping + h * e.spring.stiffness, 0.0);
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 3000);
}

TEST(ExactSoftness, UndampedGivesTheCorrectedSymplecticSpring) {
  const double m = 1.7, h = 1.0 / 60;
  for (double f : {1.0, 5.0, 10.0, 20.0, 29.0}) {
    const double omega = 2.0 * std::numbers::pi * f;
    const ExactSpring e = exact_spring(m, omega, 0.0, h);
    // k' = 2 m (1 - cos(omega h)) / h^2 (the closed form), c' = -h k'.
    EXPECT_NEAR(e.spring.stiffness, 2.0 * m * (1.0 - std::cos(omega * h)) / (h * h), 1e-10 * e.spring.stiffness);
    EXPECT_NEAR(e.spring.damping, -h * e.spring.stiffness, 1e-12 * e.spring.stiffness);
    EXPECT_EQ(e.softness.kind, SoftnessKind::unrepresentable);
    // Its discrete poles are exp(+-i omega h): frequency exact, no damping.
    const StepModel model = make_step_model(m, omega, 0.0, h);
    const DiscreteAnalysis a = analyze(Method::soft_exact, model, omega, 0.0);
    ASSERT_TRUE(a.achieved_frequency_hz);
    EXPECT_NEAR(*a.achieved_frequency_hz, f, 1e-9 * f);
    EXPECT_NEAR(*a.achieved_damping_ratio, 0.0, 1e-9);
    EXPECT_NEAR(a.spectral_radius, 1.0, 1e-12);
  }
}

TEST(ExactSoftness, GivesBackDampingWhereImplicitEulerOverDamps) {
  // docs/math.md: c' may be negative while c' + h k' > 0 for zeta > 0.
  const double m = 1.0, h = 1.0 / 60, omega = 2.0 * std::numbers::pi * 10.0;
  const ExactSpring e = exact_spring(m, omega, 0.05, h);
  EXPECT_LT(e.spring.damping, 0.0);
  EXPECT_GT(e.spring.damping + h * e.spring.stiffness, 0.0);
  EXPECT_EQ(e.softness.kind, SoftnessKind::soft);
  // gamma', beta' are the talk's formulas applied to k', c'.
  const Softness s = softness_from_spring(e.spring.stiffness, e.spring.damping, h);
  EXPECT_NEAR(e.softness.gamma, s.gamma, 1e-12 * s.gamma);
  EXPECT_NEAR(e.softness.beta, s.beta, 1e-12);
}

TEST(ExactSoftness, ClampsAboveNyquist) {
  const double h = 1.0 / 60;
  for (double zeta : {0.0, 0.3, 0.9}) {
    const double max_omega = exact_max_omega(zeta, h);
    EXPECT_NEAR(max_omega * std::sqrt(1 - zeta * zeta) * h, std::numbers::pi * (1 - kNyquistMargin), 1e-12);
    const ExactSpring e = exact_spring(1.0, 2.0 * max_omega, zeta, h);
    EXPECT_TRUE(e.clamped_to_nyquist);
    EXPECT_DOUBLE_EQ(e.omega, max_omega);
    EXPECT_TRUE(std::isfinite(e.spring.stiffness));
  }
  EXPECT_TRUE(std::isinf(exact_max_omega(1.0, h)));
  EXPECT_FALSE(exact_spring(1.0, 1e6, 2.0, h).clamped_to_nyquist);
}

TEST(ExactSoftness, SmallStepsStayPrecise) {
  // omega h = 1e-5: the closed forms cancel badly unless written with expm1 and sin^2 (see the header).
  const double m = 1.0, omega = 10.0, h = 1e-6, zeta = 0.5;
  const ExactSpring e = exact_spring(m, omega, zeta, h);
  // As h -> 0, k' -> k and c' -> c.
  EXPECT_NEAR(e.spring.stiffness, m * omega * omega, 1e-3 * m * omega * omega);
  EXPECT_NEAR(e.spring.damping, 2 * m * zeta * omega, 1e-3 * 2 * m * zeta * omega);
}

TEST(ExactSoftness, OverflowIsReportedNotReturnedAsInfinity) {
  const ExactSpring e = exact_spring(1.0, 1e4, 1000.0, 0.1);  // zeta omega h = 1e6
  EXPECT_FALSE(e.finite);
  EXPECT_TRUE(std::isfinite(e.spring.stiffness));
  const StepModel model = make_step_model(1.0, 1e4, 1000.0, 0.1);
  EXPECT_TRUE(std::isfinite(model.exact.spring.stiffness));
  EXPECT_EQ(model.exact.softness.kind, SoftnessKind::soft);
}
