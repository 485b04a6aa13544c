#include "softtune/discrete_analysis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace softtune;

namespace {
constexpr double kPi = std::numbers::pi;

DiscreteAnalysis analyze_at(Method m, double omega, double zeta, double h, double mass = 1.0) {
  return analyze(m, make_step_model(mass, omega, zeta, h), omega, zeta);
}

// Largest stable step found by bisection on the spectral radius: an independent check of the closed forms.
double bisect_max_h(Method m, double omega, double zeta) {
  double lo = 1e-9 / omega, hi = 100.0 / omega;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    const double r = analyze_at(m, omega, zeta, mid).spectral_radius;
    (r <= 1.0 + 1e-12 ? lo : hi) = mid;
  }
  return lo;
}
}  // namespace

TEST(DiscreteAnalysis, StepMatrixOfSemiImplicitEuler) {
  // A = [[1 - h^2 w^2, h - 2 zeta w h^2], [-h w^2, 1 - 2 zeta w h]] for unit mass.
  const double w = 3.0, z = 0.2, h = 0.1;
  const Eigen::Matrix2d a = step_matrix(Method::semi_implicit_euler, make_step_model(1.0, w, z, h));
  EXPECT_NEAR(a(0, 0), 1 - h * h * w * w, 1e-15);
  EXPECT_NEAR(a(0, 1), h - 2 * z * w * h * h, 1e-15);
  EXPECT_NEAR(a(1, 0), -h * w * w, 1e-15);
  EXPECT_NEAR(a(1, 1), 1 - 2 * z * w * h, 1e-15);
}

TEST(DiscreteAnalysis, ExplicitEulerIsUnstableUndampedForEveryStep) {
  // rho = sqrt(1 + (omega h)^2) > 1 (Catto GDC 2011, "1:2:1": "it always blows up").
  for (double x = 1e-3; x < 100; x *= 1.3) {
    const DiscreteAnalysis a = analyze_at(Method::explicit_euler, 1.0, 0.0, x);
    EXPECT_NEAR(a.spectral_radius, std::sqrt(1 + x * x), 1e-12 * a.spectral_radius);
    EXPECT_EQ(a.verdict, Verdict::unstable) << x;
  }
  EXPECT_EQ(*max_stable_step(Method::explicit_euler, 1.0, 0.0), 0.0);
}

TEST(DiscreteAnalysis, SemiImplicitIsStableUndampedIffOmegaHBelowTwo) {
  for (double x = 0.01; x < 6.0; x += 0.01) {
    if (std::abs(x - 2.0) < 1e-6) continue;
    const DiscreteAnalysis a = analyze_at(Method::semi_implicit_euler, 1.0, 0.0, x);
    EXPECT_EQ(a.verdict != Verdict::unstable, x < 2.0) << x;
  }
  EXPECT_NEAR(*max_stable_step(Method::semi_implicit_euler, 5.0, 0.0), 2.0 / 5.0, 1e-15);
}

TEST(DiscreteAnalysis, ImplicitAndSoftAreStableForEveryStep) {
  for (double zeta : {0.0, 0.01, 0.5, 1.0, 10.0, 1000.0}) {
    for (double x = 1e-4; x < 1e6; x *= 1.7) {
      for (Method m : {Method::implicit_euler, Method::soft}) {
        const DiscreteAnalysis a = analyze_at(m, 1.0, zeta, x);
        EXPECT_LT(a.spectral_radius, 1.0) << method_name(m) << " zeta " << zeta << " x " << x;
        EXPECT_FALSE(a.max_stable_h.has_value());
      }
      EXPECT_NE(analyze_at(Method::soft_exact, 1.0, zeta, x).verdict, Verdict::unstable) << zeta << " " << x;
    }
  }
}

TEST(DiscreteAnalysis, ClosedFormLimitsMatchBisection) {
  for (double zeta : {0.05, 0.3, 0.7, 1.0, 1.5, 4.0}) {
    for (Method m : {Method::explicit_euler, Method::semi_implicit_euler}) {
      const double omega = 7.0;
      const double closed = *max_stable_step(m, omega, zeta);
      EXPECT_NEAR(bisect_max_h(m, omega, zeta), closed, 1e-6 * closed) << method_name(m) << " " << zeta;
    }
  }
}

TEST(DiscreteAnalysis, StepsPerPeriodAndTheRuleOfThumb) {
  // 15 Hz at 60 Hz steps is 4 steps per period: the talk's rule of thumb ("1:2:2").
  const DiscreteAnalysis a = analyze_at(Method::semi_implicit_euler, 2 * kPi * 15, 0.0, 1.0 / 60);
  EXPECT_NEAR(*a.steps_per_period, 4.0, 1e-12);
  EXPECT_FALSE(analyze_at(Method::soft, 0.0, 0.0, 0.01).steps_per_period.has_value());
}

TEST(DiscreteAnalysis, AchievedFrequencyFromKnownPoles) {
  const double h = 0.01, omega = 20.0, zeta = 0.3;
  const std::complex<double> s(-zeta * omega, omega * std::sqrt(1 - zeta * zeta));
  double f = 0, z = 0;
  ASSERT_TRUE(achieved_from_poles(std::exp(s * h), std::exp(std::conj(s) * h), h, f, z));
  EXPECT_NEAR(f, omega / (2 * kPi), 1e-12);
  EXPECT_NEAR(z, zeta, 1e-12);
  // Over-damped: two positive real poles.
  const double s1 = -2.0, s2 = -50.0;
  ASSERT_TRUE(achieved_from_poles(std::exp(s1 * h), std::exp(s2 * h), h, f, z));
  EXPECT_NEAR(f, std::sqrt(s1 * s2) / (2 * kPi), 1e-10);
  EXPECT_NEAR(z, -(s1 + s2) / (2 * std::sqrt(s1 * s2)), 1e-10);
  // A zero pole has no frequency.
  EXPECT_FALSE(achieved_from_poles(0.0, 0.5, h, f, z));
  // Poles on the unit circle (semi-implicit Euler, exact softness at zeta 0): undamped, +0 and not -0,
  // which reports and CSV files would print as "-0".
  const std::complex<double> on_circle = std::polar(1.0, omega * h);
  ASSERT_TRUE(achieved_from_poles(on_circle, std::conj(on_circle), h, f, z));
  EXPECT_EQ(z, 0.0);
  EXPECT_FALSE(std::signbit(z));
  EXPECT_NEAR(f, omega / (2 * kPi), 1e-12);
}

TEST(DiscreteAnalysis, ImplicitEulerSlowsAndDampsAsTheSpecSays) {
  // docs/math.md: asked 10 Hz free at 60 fps, implicit Euler gives 7.7 Hz (the visible, damped frequency)
  // with zeta 0.42; asked 15 Hz: 9.6 Hz, zeta 0.53.
  const DiscreteAnalysis ten = analyze_at(Method::soft, 2 * kPi * 10, 0.0, 1.0 / 60);
  EXPECT_NEAR(*ten.achieved_damped_frequency_hz, 7.7, 0.05);
  EXPECT_NEAR(*ten.achieved_damping_ratio, 0.42, 0.005);
  const DiscreteAnalysis fifteen = analyze_at(Method::soft, 2 * kPi * 15, 0.0, 1.0 / 60);
  EXPECT_NEAR(*fifteen.achieved_damped_frequency_hz, 9.6, 0.05);
  EXPECT_NEAR(*fifteen.achieved_damping_ratio, 0.53, 0.005);
}

TEST(DiscreteAnalysis, RecurrenceOfASampledDampedOscillatorGivesItsFrequencyAndDamping) {
  // x(t) = e^{-zeta omega t} cos(omega_d t) sampled every h obeys x[n] = 2 r cos(omega_d h) x[n-1] - r^2 x[n-2]
  // with r = e^{-zeta omega h}: its poles are e^{s h}, and reading them returns omega and zeta exactly.
  const double h = 1.0 / 60, omega = 2 * kPi * 3.0, zeta = 0.2;
  const double r = std::exp(-zeta * omega * h), wd = omega * std::sqrt(1 - zeta * zeta);
  const RecurrencePoles poles = poles_of_recurrence(2 * r * std::cos(wd * h), -r * r, h);
  ASSERT_TRUE(poles.frequency_hz && poles.damping_ratio);
  EXPECT_NEAR(*poles.frequency_hz, 3.0, 1e-12);
  EXPECT_NEAR(*poles.damping_ratio, zeta, 1e-12);
  EXPECT_NEAR(std::abs(poles.z1), r, 1e-15);
  // A decaying exponential alone (q = 0): one pole at e^{-a h}, one at zero, so no frequency to read.
  const RecurrencePoles decay = poles_of_recurrence(std::exp(-5.0 * h), 0.0, h);
  EXPECT_FALSE(decay.frequency_hz.has_value());
}

TEST(DiscreteAnalysis, EigenvaluesOfRealMatrices) {
  std::complex<double> z1, z2;
  Eigen::Matrix2d a;
  a << 2, 0, 0, -3;
  eigenvalues_2x2(a, z1, z2);
  EXPECT_NEAR(std::max(std::abs(z1), std::abs(z2)), 3.0, 1e-15);
  EXPECT_NEAR(std::min(std::abs(z1), std::abs(z2)), 2.0, 1e-15);
  a << 0, -1, 1, 0;  // rotation by 90 degrees
  eigenvalues_2x2(a, z1, z2);
  EXPECT_NEAR(z1.real(), 0.0, 1e-15);
  EXPECT_NEAR(std::abs(z1.imag()), 1.0, 1e-15);
}

TEST(DiscreteAnalysis, MarginalBandIsDocumentedClass) {
  EXPECT_EQ(classify_spectral_radius(1.0), Verdict::marginal);
  EXPECT_EQ(classify_spectral_radius(1.0 + 0.5e-9), Verdict::marginal);
  EXPECT_EQ(classify_spectral_radius(1.0 + 2e-9), Verdict::unstable);
  EXPECT_EQ(classify_spectral_radius(0.99), Verdict::stable);
  EXPECT_EQ(classify_spectral_radius(NAN), Verdict::unstable);
}
