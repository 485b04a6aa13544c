#include "softtune/tune.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "softtune/exact_softness.h"
#include "softtune/validation.h"

using namespace softtune;

namespace {
TuneRequest basic(double frames, Oscillation level, double mass, SoftMode mode = SoftMode::standard) {
  TuneRequest r;
  r.response_frames = frames;
  r.oscillation = level;
  r.effective_mass = mass;
  r.mode = mode;
  return r;
}
bool has_warning(const TuneResult& r, WarningCode code) {
  return std::any_of(r.warnings.begin(), r.warnings.end(), [code](const Warning& w) { return w.code == code; });
}
}  // namespace

TEST(Tune, TwelveFramesSomeOscillation) {
  const TuneRequest q = basic(12, Oscillation::some, 2.0);
  ASSERT_FALSE(validate_tune_request(q));
  const TuneResult r = tune(q);
  const double omega = 2 * M_PI * 5.0, h = 1.0 / 60;
  EXPECT_DOUBLE_EQ(r.frequency_hz, 5.0);
  EXPECT_DOUBLE_EQ(r.damping_ratio, 0.5);
  EXPECT_NEAR(r.spring.stiffness, 2.0 * omega * omega, 1e-9);
  EXPECT_NEAR(r.spring.damping, 2.0 * 2.0 * 0.5 * omega, 1e-12);
  const double denominator = r.spring.damping + h * r.spring.stiffness;
  EXPECT_NEAR(r.softness.gamma, 1.0 / denominator, 1e-15);
  EXPECT_NEAR(r.softness.beta, h * r.spring.stiffness / denominator, 1e-15);
  ASSERT_TRUE(r.box2d_v3);
  EXPECT_NEAR(r.box2d_v3->mass_scale + r.box2d_v3->impulse_scale, 1.0, 1e-15);
  EXPECT_TRUE(r.stages.contains(Stage::engine_export));
  EXPECT_FALSE(r.stages.contains(Stage::effective_mass));  // given directly: nothing to compute
}

TEST(Tune, ExactModeAchievesTheRequest) {
  for (double frames : {60.0, 12.0, 6.0, 4.0, 2.5}) {
    for (Oscillation level : {Oscillation::free, Oscillation::some, Oscillation::none}) {
      const TuneResult r = tune(basic(frames, level, 3.0, SoftMode::exact));
      ASSERT_TRUE(r.achieved_frequency_hz) << frames;
      EXPECT_NEAR(*r.achieved_frequency_hz / r.frequency_hz, 1.0, 1e-9) << frames;
      EXPECT_NEAR(*r.achieved_damping_ratio, r.damping_ratio, 1e-7) << frames;
      EXPECT_FALSE(has_warning(r, WarningCode::nyquist_clamped));
    }
  }
}

TEST(Tune, StandardModeWarnsWhenItMissesTheFrequency) {
  const TuneResult r = tune(basic(6, Oscillation::free, 1.0));  // 10 Hz free at 60 fps
  EXPECT_TRUE(has_warning(r, WarningCode::frequency_error));
  EXPECT_NEAR(*r.achieved_damping_ratio, 0.416, 0.001);
}

TEST(Tune, ExactUndampedReportsNoGammaButKeepsTheSpring) {
  const TuneResult r = tune(basic(6, Oscillation::free, 1.0, SoftMode::exact));
  EXPECT_TRUE(has_warning(r, WarningCode::gamma_unrepresentable));
  EXPECT_EQ(r.softness.kind, SoftnessKind::unrepresentable);
  const double h = 1.0 / 60, omega = 2 * M_PI * 10;
  EXPECT_NEAR(r.spring.stiffness, 2.0 * (1 - std::cos(omega * h)) / (h * h), 1e-9);
  EXPECT_FALSE(r.box2d_v3.has_value());
}

TEST(Tune, AboveNyquistClampsInExactModeAndWarnsInStandard) {
  const TuneResult exact = tune(basic(1.0, Oscillation::some, 1.0, SoftMode::exact));  // 60 Hz at 60 fps
  EXPECT_TRUE(has_warning(exact, WarningCode::nyquist_clamped));
  EXPECT_LT(exact.frequency_hz, 60.0);
  EXPECT_NEAR(exact.frequency_hz * std::sqrt(1 - 0.25), 30.0 * (1 - kNyquistMargin), 1e-9);  // just below Nyquist
  const TuneResult standard = tune(basic(1.0, Oscillation::some, 1.0));
  EXPECT_TRUE(has_warning(standard, WarningCode::above_nyquist));
  EXPECT_TRUE(has_warning(standard, WarningCode::few_steps_per_period));
  for (const TuneResult* r : {&exact, &standard}) {
    EXPECT_TRUE(std::isfinite(r->spring.stiffness));
    EXPECT_TRUE(std::isfinite(r->softness.gamma));
  }
}

TEST(Tune, ZeroFrequencyIsNoConstraint) {
  TuneRequest q = basic(12, Oscillation::some, 1.0);
  q.response_frames.reset();
  q.frequency_hz = 0.0;
  ASSERT_FALSE(validate_tune_request(q));
  const TuneResult r = tune(q);
  EXPECT_TRUE(has_warning(r, WarningCode::no_constraint));
  EXPECT_EQ(r.softness.kind, SoftnessKind::no_constraint);
}

TEST(Tune, ConstraintRunsTheEffectiveMassStageAndChecksIt) {
  TuneRequest q = basic(12, Oscillation::some, 1.0);
  q.effective_mass.reset();
  Constraint2D c;
  c.body_a.is_static = true;
  c.body_b.mass = 4.0;
  c.body_b.inertia = 4.0 * 4.0 / 12.0;  // a 2 m plank
  c.anchor_a = {1.0, 1.0};
  c.anchor_b = {1.0, 0.0};
  c.axis = {0.0, 2.0};  // not unit: normalized with a warning
  q.constraint = c;
  ASSERT_FALSE(validate_tune_request(q));
  const TuneResult r = tune(q);
  EXPECT_TRUE(r.stages.contains(Stage::effective_mass));
  EXPECT_NEAR(1.0 / r.effective_mass, 1.0 / 4.0 + 1.0 / (4.0 / 3.0), 1e-14);
  EXPECT_NEAR(r.inverse_effective_mass_impulse, 1.0 / r.effective_mass, 1e-14);
  EXPECT_TRUE(has_warning(r, WarningCode::axis_normalized));
  // b2LinearStiffness uses 4 kg where the constraint sees 1 kg: its spring runs at twice the frequency.
  ASSERT_TRUE(r.engines.box2d_v2_4.linear_stiffness_frequency_error);
  EXPECT_NEAR(*r.engines.box2d_v2_4.linear_stiffness_frequency_error, 1.0, 1e-12);
  EXPECT_TRUE(has_warning(r, WarningCode::box2d_reduced_mass_error));
}

TEST(Tune, StabilityCoversEveryIntegrator) {
  const TuneResult r = tune(basic(3, Oscillation::free, 1.0));  // 20 Hz at 60 fps: omega h = 2.09
  EXPECT_EQ(r.stability[0].verdict, Verdict::unstable);  // explicit
  EXPECT_EQ(r.stability[1].verdict, Verdict::unstable);  // semi-implicit: omega h > 2
  EXPECT_NE(r.stability[2].verdict, Verdict::unstable);  // implicit
  EXPECT_NE(r.stability[3].verdict, Verdict::unstable);  // soft
  EXPECT_NE(r.stability[4].verdict, Verdict::unstable);  // soft exact
}

TEST(Tune, SubstepsShrinkTheStep) {
  TuneRequest q = basic(12, Oscillation::some, 1.0);
  q.substeps = 4;
  EXPECT_DOUBLE_EQ(tune(q).h, 1.0 / 240);
}
