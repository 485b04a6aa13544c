// The sweep's prediction (step matrix) equals its observation (simulation) on every case, the soft
// constraint never blows up, and known stability limits hold on both sides.
#include "softtune/stability_sweep.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace softtune {
namespace {

TEST(StabilitySweep, DefaultSweepPredictionEqualsObservation) {
  const SweepSettings settings = default_sweep_settings();
  const SweepResult r = run_sweep(settings);
  EXPECT_GE(r.summary.cases, 10000u);
  EXPECT_EQ(r.summary.mismatches, 0u);
  EXPECT_EQ(r.summary.soft_blowups, 0u);
  EXPECT_EQ(r.summary.non_finite_values, 0u);
  // All three classes occur, so the equality is not vacuous.
  EXPECT_GT(r.summary.predicted_stable, 1000u);
  EXPECT_GT(r.summary.predicted_marginal, 100u);
  EXPECT_GT(r.summary.predicted_unstable, 1000u);
  int reported = 0;
  for (const SweepCase& c : r.cases) {
    if (c.observed != c.predicted && reported++ < 10) {
      ADD_FAILURE() << method_name(c.method) << " f h " << c.frequency_ratio << " zeta " << c.damping_ratio << " m "
                    << c.mass << " k " << c.stiffness << " h " << c.h << " rho " << c.spectral_radius;
    }
    ASSERT_TRUE(std::isfinite(c.spectral_radius));
    if (c.observed_spectral_radius) {
      ASSERT_TRUE(std::isfinite(*c.observed_spectral_radius));
    }
  }
}

TEST(StabilitySweep, DefaultGridSpansTheIssuesRanges) {
  const SweepSettings s = default_sweep_settings();
  EXPECT_DOUBLE_EQ(s.frequency_ratios.front(), 0.001);
  EXPECT_DOUBLE_EQ(s.frequency_ratios.back(), 2.0);
  EXPECT_EQ(s.damping_ratios, (std::vector<double>{0, 1e-3, 0.1, 0.5, 1, 10, 1000}));
  EXPECT_DOUBLE_EQ(s.masses.front(), 1e-6);
  EXPECT_DOUBLE_EQ(s.masses.back(), 1e6);
  EXPECT_DOUBLE_EQ(s.stiffnesses.back(), 1e12);
  EXPECT_DOUBLE_EQ(s.steps.front(), 1e-6);
  EXPECT_DOUBLE_EQ(s.steps.back(), 0.1);
  EXPECT_EQ(s.methods.size(), kAllMethods.size());
}

SweepCase make(Method m, double omega_h, double zeta, double h = 0.01, double mass = 1.0) {
  SweepCase c;
  c.method = m;
  c.damping_ratio = zeta;
  c.mass = mass;
  c.h = h;
  const double omega = omega_h / h;
  c.stiffness = mass * omega * omega;
  c.frequency_ratio = omega_h / (2.0 * std::numbers::pi);
  return run_sweep_case(c, 1000);
}

// Semi-implicit Euler's closed-form limit omega h < 2 (sqrt(zeta^2 + 1) - zeta): both sides.
TEST(StabilitySweep, SemiImplicitLimitOnBothSides) {
  for (double zeta : {0.0, 0.5, 1.0}) {
    const double limit = 2.0 * (std::sqrt(zeta * zeta + 1.0) - zeta);
    const SweepCase inside = make(Method::semi_implicit_euler, 0.99 * limit, zeta);
    const SweepCase outside = make(Method::semi_implicit_euler, 1.01 * limit, zeta);
    EXPECT_NE(inside.predicted, Verdict::unstable) << zeta;
    EXPECT_EQ(inside.observed, inside.predicted) << zeta;
    EXPECT_EQ(outside.predicted, Verdict::unstable) << zeta;
    EXPECT_EQ(outside.observed, Verdict::unstable) << zeta;
  }
  EXPECT_EQ(make(Method::semi_implicit_euler, 1.0, 0.0).predicted, Verdict::marginal);
}

// Explicit Euler undamped: |z| = sqrt(1 + (omega h)^2), unstable however small h is.
TEST(StabilitySweep, ExplicitEulerUndampedAlwaysGrows) {
  for (double omega_h : {1e-3, 0.1, 1.0, 10.0}) {
    const SweepCase c = make(Method::explicit_euler, omega_h, 0.0);
    EXPECT_NEAR(c.spectral_radius, std::sqrt(1.0 + omega_h * omega_h), 1e-12);
    EXPECT_EQ(c.observed, Verdict::unstable) << omega_h;
  }
}

// The soft constraint, standard and exact, is stable at any stiffness, mass and step.
TEST(StabilitySweep, SoftNeverBlowsUpOnExtremes) {
  for (Method m : {Method::soft, Method::soft_exact}) {
    for (double omega_h : {1e-4, 3.0, 1e3, 1e6}) {
      for (double zeta : {0.0, 1e-3, 1.0, 1000.0}) {
        const SweepCase c = make(m, omega_h, zeta, 0.1, 1e-6);
        EXPECT_NE(c.observed, Verdict::unstable) << method_name(m) << " " << omega_h << " " << zeta;
        EXPECT_EQ(c.observed, c.predicted);
      }
    }
  }
}

// Regression: exact mode clamped at Nyquist with zeta = 0 used to land on a double pole at z = -1 (a
// Jordan block: the motion grew linearly). The clamp keeps a margin, so the motion stays bounded.
TEST(StabilitySweep, ExactClampAtNyquistStaysBounded) {
  const double h = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 45.0;
  const StepModel model = make_step_model(1.0, omega, 0.0, h);
  EXPECT_TRUE(model.exact.clamped_to_nyquist);
  State s{1.0, 0.0};
  double peak = 0.0;
  for (int i = 0; i < 100000; ++i) {
    s = step(Method::soft_exact, s, model);
    peak = std::max(peak, std::abs(s.x));
  }
  // Bounded by 1 / cos(theta / 2) with theta = 0.99 pi: about 64 amplitudes, however long it runs.
  EXPECT_LT(peak, 1.0 / std::cos(0.5 * (1.0 - kNyquistMargin) * std::numbers::pi) + 1.0);
  const auto rho = observed_spectral_radius(Method::soft_exact, model, 1000);
  ASSERT_TRUE(rho);
  EXPECT_EQ(classify_spectral_radius(*rho), Verdict::marginal);
}

// A damped run of 100 000 steps shrinks the states by e^-15000, far below the smallest double: the
// observation rescales them and still finds the step matrix's own spectral radius (Gelfand), where
// the unscaled run would end in zeros or subnormal digits.
TEST(StabilitySweep, ObservedRadiusOfADeeplyDecayedRunMatchesTheStepMatrix) {
  const double h = 0.01, omega = 2.0 * std::numbers::pi * 5.0, zeta = 0.5;
  const StepModel model = make_step_model(1.0, omega, zeta, h);
  for (Method m : {Method::semi_implicit_euler, Method::implicit_euler, Method::soft, Method::soft_exact}) {
    const double predicted = analyze(m, model, omega, zeta).spectral_radius;
    ASSERT_LT(std::pow(predicted, 100000), 1e-300) << method_name(m);
    const auto observed = observed_spectral_radius(m, model, 100000);
    ASSERT_TRUE(observed) << method_name(m);
    EXPECT_NEAR(*observed, predicted, 1e-6 * predicted) << method_name(m);
  }
}

// The count a job reports as its total is the number of cases the sweep runs, frequency cases above
// max_stiffness left out (k = m (2 pi f h / h)^2: at f h = 2, h = 1e-3, m = 1 kg, k = 1.6e8 N/m).
TEST(StabilitySweep, CaseCountIsTheCasesRunAndProgressStopsTheSweep) {
  SweepSettings s = default_sweep_settings();
  s.methods = {Method::soft, Method::semi_implicit_euler};
  s.frequency_ratios = {0.01, 0.5, 2.0};
  s.stiffnesses = {1.0, 1e4};
  s.damping_ratios = {0.0, 1.0};
  s.masses = {1.0};
  s.steps = {1e-3, 0.1};
  s.max_stiffness = 1e8;
  s.observe_steps = 1000;
  const SweepResult all = run_sweep(s);
  // h = 1e-3: f h = 2 gives 1.6e8 > 1e8 (skipped), 0.5 gives 9.9e6; h = 0.1 keeps all three.
  EXPECT_EQ(all.cases.size(), 2u * 2u * ((2 + 2) + (3 + 2)));
  EXPECT_EQ(sweep_case_count(s), all.cases.size());

  std::size_t calls = 0;
  const SweepResult stopped = run_sweep(s, [&] { return ++calls < 5; });
  EXPECT_EQ(calls, 5u);
  EXPECT_EQ(stopped.cases.size(), 5u);
  std::size_t every = 0;
  run_sweep(s, [&] { return ++every > 0; });
  EXPECT_EQ(every, all.cases.size());
}

}  // namespace
}  // namespace softtune
