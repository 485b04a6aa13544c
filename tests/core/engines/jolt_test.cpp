// Jolt's model against the engine's own equations (SpringPart.h, MotionProperties.inl, PhysicsSystem.cpp):
// each collision step scales the velocity by max(0, 1 - mLinearDamping h), then solves the soft row, which
// is implicit Euler on (m_eff, k, c) at h = dt / collisionSteps; exact parameters are softtune's exact spring
// at h corrected for that scale.
#include "softtune/engines/jolt.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"
#include "softtune/integrators.h"

namespace softtune::engines {
namespace {

using testing::kPi;

using testing::target;

SettingValues jolt_settings(int collision_steps, double linear_damping, int mode = 0) {
  SettingValues v = default_settings(kJoltModel);
  v[kJoltCollisionSteps] = collision_steps;
  v[kJoltLinearDamping] = linear_damping;
  v[kJoltSpringMode] = mode;
  return v;
}

TEST(JoltModel, DefaultsAreTheEngines) {
  const SettingValues d = default_settings(kJoltModel);
  EXPECT_EQ(d[kJoltCollisionSteps], 1);
  EXPECT_EQ(d[kJoltNumVelocitySteps], 10);  // PhysicsSettings.h
  EXPECT_EQ(d[kJoltNumPositionSteps], 2);
  EXPECT_EQ(d[kJoltSpringMode], 0);         // ESpringMode::FrequencyAndDamping
  EXPECT_EQ(d[kJoltLinearDamping], 0.05);   // BodyCreationSettings::mLinearDamping
  EXPECT_EQ(kJoltModel.settings[kJoltSpringMode].choices[2], "MassNormalizedStiffnessAndDamping");
}

TEST(JoltModel, StepMapIsDampedImplicitEulerPerCollisionStep) {
  const double m = 3.0, k = 500.0, c = 4.0, dt = 1.0 / 60.0, damping = 0.7;
  for (int n : {1, 2, 5}) {
    const Eigen::Matrix2d a = jolt_step_map(m, k, c, dt, n, damping);
    const double h = dt / n;
    for (State s0 : {State{1.0, 0.0}, State{0.0, 1.0}, State{0.3, -2.0}}) {
      State s = s0;
      for (int i = 0; i < n; ++i) {
        s.v *= 1.0 - damping * h;  // ApplyForceTorqueAndDragInternal
        s = implicit_euler_step(s, Oscillator{m, k, c}, h);
      }
      EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s.x, 1e-12) << n;
      EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s.v, 1e-12) << n;
    }
  }
}

TEST(JoltModel, StandardExportWithoutDampingPredictsImplicitEuler) {
  // docs/math.md: asked 10 Hz free at 60 fps, standard softness gives 8.49 Hz natural with zeta 0.416.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 10.0;
  const EngineReport r = kJoltModel.report(target(10.0, 0.0, m, h, spring_constants(m, omega, 0.0)), jolt_settings(1, 0.0));
  ASSERT_TRUE(r.predicted.frequency_hz);
  EXPECT_NEAR(*r.predicted.frequency_hz, 8.49, 0.01);
  EXPECT_NEAR(*r.predicted.damping_ratio, 0.416, 0.001);
  // FrequencyAndDamping: what is typed is the frequency and ratio of k, c on the constraint's own m_eff.
  EXPECT_EQ(r.parameters[0].choice, "FrequencyAndDamping");
  EXPECT_NEAR(*parameter_value(r.parameters, "SpringSettings::mFrequency"), 10.0, 1e-12);
  EXPECT_EQ(*parameter_value(r.parameters, "SpringSettings::mDamping"), 0.0);
}

TEST(JoltModel, DefaultLinearDampingAddsItsOwnDampingRatio) {
  // v *= 1 - d h per step multiplies the poles' product by (1 - d h)^2: at small omega h the damping ratio
  // grows by about d / (2 omega) over implicit Euler's.
  const double m = 2.0, h = 1.0 / 240.0, hz = 0.5, omega = 2.0 * kPi * hz;
  const Target t = target(hz, 0.1, m, h, spring_constants(m, omega, 0.1));
  const EngineReport plain = kJoltModel.report(t, jolt_settings(1, 0.0));
  const EngineReport damped = kJoltModel.report(t, default_settings(kJoltModel));
  EXPECT_NEAR(*damped.predicted.damping_ratio - *plain.predicted.damping_ratio, 0.05 / (2.0 * omega), 2e-4);
}

TEST(JoltModel, ExactIsTheExactSpringCorrectedForDamping) {
  const double m = 0.5, dt = 1.0 / 60.0;
  for (int n : {1, 3}) {
    for (double zeta : {0.1, 0.5, 1.5}) {
      const double hz = 7.0, omega = 2.0 * kPi * hz, d = 0.05, h = dt / n;
      const EngineReport r = kJoltModel.report(target(hz, zeta, m, dt, spring_constants(m, omega, zeta)),
                                               jolt_settings(n, d, /*StiffnessAndDamping*/ 1));
      ASSERT_TRUE(r.exact && r.exact_predicted) << n << " " << zeta;
      const ExactSpring e = exact_spring(m, omega, zeta, h);
      const double a = 1.0 - d * h;
      EXPECT_NEAR(*parameter_value(*r.exact, "SpringSettings::mStiffness"), a * e.spring.stiffness,
                  1e-9 * e.spring.stiffness);
      EXPECT_NEAR(*parameter_value(*r.exact, "SpringSettings::mDamping"), a * e.spring.damping - m * (1 - a) / h,
                  1e-9 * e.spring.stiffness * h);
      EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-9 * hz);
      EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 1e-9);
      // The engine's own step with those numbers has the asked poles (exact_predicted is not computed
      // from the map on this path).
      const Prediction p = predict_from_step_map(
          jolt_step_map(m, *parameter_value(*r.exact, "SpringSettings::mStiffness"),
                        *parameter_value(*r.exact, "SpringSettings::mDamping"), dt, n, d), dt);
      EXPECT_NEAR(*p.frequency_hz, hz, 1e-9 * hz);
      EXPECT_NEAR(*p.damping_ratio, zeta, 1e-9);
      EXPECT_NEAR(p.spectral_radius, r.exact_predicted->spectral_radius, 1e-12);
    }
  }
}

TEST(JoltModel, ExactUndampedIsTheLeastDampedSpringItTakes) {
  // Without linear damping, zeta = 0 needs c + h k = 0 (SpringPart divides by it): the nearest legal spring,
  // c + h k = 2e-4 h k, damps by about 1e-4 omega h and meets the request.
  const double m = 1.0, h = 1.0 / 60.0, hz = 5.0, omega = 2.0 * kPi * hz;
  const EngineReport r = kJoltModel.report(target(hz, 0.0, m, h, spring_constants(m, omega, 0.0)), jolt_settings(1, 0.0, 1));
  ASSERT_TRUE(r.exact && r.exact_predicted);
  const double k = *parameter_value(*r.exact, "SpringSettings::mStiffness");
  const double c = *parameter_value(*r.exact, "SpringSettings::mDamping");
  EXPECT_GE(c + h * k, kJoltFloatMargin * h * k);
  EXPECT_LE(*r.exact_predicted->damping_ratio, kExactDampingTolerance);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, hz * kExactFrequencyTolerance);
}

TEST(JoltModel, DefaultDampingMakesASlowUndampedSpringInexact) {
  // With mLinearDamping 0.05 the least damping at 0.3 Hz is about 0.05 / (2 omega) = 0.013 > 0.005.
  const double m = 1.0, h = 1.0 / 60.0, hz = 0.3, omega = 2.0 * kPi * hz;
  const EngineReport r = kJoltModel.report(target(hz, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                           default_settings(kJoltModel));
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
  EXPECT_EQ(r.warnings.back().engine, "jolt");
  EXPECT_NEAR(r.warnings.back().limit, 0.05 / (2.0 * omega), 1e-3);  // damping error of the nearest
  // Within 1 % / 0.02, the nearest legal spring is given as exact, flagged by that warning, its prediction
  // the asked frequency with the linear damping's extra ratio.
  ASSERT_TRUE(r.exact && r.exact_predicted);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-3 * hz);
  EXPECT_NEAR(*r.exact_predicted->damping_ratio, 0.05 / (2.0 * omega), 1e-3);
  EXPECT_DOUBLE_EQ(r.warnings.back().limit, *r.exact_predicted->damping_ratio);
  // At 0.1 Hz the same damping costs 0.05 / (2 omega) = 0.04 > 0.02: no exact.
  const double omega01 = 2.0 * kPi * 0.1;
  const EngineReport slow = kJoltModel.report(target(0.1, 0.0, m, h, spring_constants(m, omega01, 0.0)),
                                              default_settings(kJoltModel));
  EXPECT_FALSE(slow.exact);
  EXPECT_EQ(slow.warnings.back().code, WarningCode::engine_inexact);
  // ...and at 5 Hz the same damping costs only 0.0008: exact exists.
  const double omega5 = 2.0 * kPi * 5.0;
  EXPECT_TRUE(kJoltModel.report(target(5.0, 0.0, m, h, spring_constants(m, omega5, 0.0)),
                                default_settings(kJoltModel)).exact);
}

TEST(JoltModel, ARefusedExportPredictsWhatTheEngineRuns) {
  // softtune's exact mode at zeta = 0 gives c' = -h k': SpringPart's softness 1 / (h (c + h k)) is computed
  // in float. Where c + h k is exactly 0 there (h = 1/64, k = 1024, c = -16) it is infinite, the row's
  // effective mass 0 and the row inactive: the body moves free, poles 1 and the damping scale, no frequency.
  const double m = 1.0;
  {
    const double h = 1.0 / 64.0, k = 1024.0;
    testing::expect_refused_and_held(kJoltModel.report(target(5.0, 0.0, m, h, {k, -h * k}), jolt_settings(1, 0.05, 1)));
  }
  // At h = 1/60 the float sum keeps a few ulp of h k: the step is symplectic Euler on an undamped spring,
  // cos(omega_d h) = 1 - h^2 k / (2 m), with mLinearDamping's scale a = 1 - 0.05 h on the velocity.
  {
    const double h = 1.0 / 60.0, k = 1000.0;
    ASSERT_NE(static_cast<float>(-h * k) + static_cast<float>(h) * static_cast<float>(k), 0.0f);
    const EngineReport r = kJoltModel.report(target(5.0, 0.0, m, h, {k, -h * k}), jolt_settings(1, 0.05, 1));
    ASSERT_TRUE(r.predicted.frequency_hz && r.predicted.damping_ratio);
    // Symplectic Euler with the scale: z^2 - (1 + a - h^2 k / m) z + a = 0.
    const double a = 1.0 - 0.05 * h, tr = 1.0 + a - h * h * k / m;
    const double sr = std::log(a) / (2.0 * h), si = std::acos(tr / (2.0 * std::sqrt(a))) / h;
    EXPECT_NEAR(*r.predicted.frequency_hz, std::hypot(sr, si) / (2.0 * kPi), 1e-4);
    EXPECT_NEAR(*r.predicted.damping_ratio, -sr / std::hypot(sr, si), 1e-5);
    EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
  }
  // Two collision steps: c + (h/2) k = -h k / 2 < 0, the soft row's algebra with the negative damping grows.
  {
    const double h = 1.0 / 60.0, k = 1000.0;
    const EngineReport r = kJoltModel.report(target(5.0, 0.0, m, h, {k, -h * k}), jolt_settings(2, 0.0, 1));
    EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
    EXPECT_FALSE(r.predicted.stable);
    // Implicit Euler at h/2 on (m, k, -h k): det = m / (m + (h/2) c + (h/2)^2 k) per collision step, a
    // complex pair of modulus sqrt(det), so per update (two steps) the spectral radius is det = 1.075.
    const double hs = h / 2.0, det = m / (m - hs * h * k + hs * hs * k);
    EXPECT_NEAR(r.predicted.spectral_radius, det, 1e-6);  // the model steps the float h and k
    EXPECT_GT(r.predicted.spectral_radius, 1.07);
  }
  // k <= 0 would make the limit hard.
  const EngineReport hard = kJoltModel.report(target(5.0, 0.5, m, 1.0 / 60.0, {0.0, 3.0}), jolt_settings(1, 0.05, 1));
  EXPECT_EQ(hard.warnings[0].code, WarningCode::engine_refuses);
}

TEST(JoltModel, ModesTypeTheSameSpring) {
  const double m = 4.0, h = 1.0 / 120.0, hz = 3.0, zeta = 0.3, omega = 2.0 * kPi * hz;
  const SpringConstants s = spring_constants(m, omega, zeta);
  const Target t = target(hz, zeta, m, h, s);
  const EngineReport f = kJoltModel.report(t, jolt_settings(1, 0.05, 0));
  const EngineReport k = kJoltModel.report(t, jolt_settings(1, 0.05, 1));
  const EngineReport n = kJoltModel.report(t, jolt_settings(1, 0.05, 2));
  EXPECT_NEAR(*parameter_value(f.parameters, "SpringSettings::mFrequency"), hz, 1e-12);
  EXPECT_NEAR(*parameter_value(f.parameters, "SpringSettings::mDamping"), zeta, 1e-12);
  EXPECT_NEAR(*parameter_value(k.parameters, "SpringSettings::mStiffness"), s.stiffness, 1e-9);
  EXPECT_NEAR(*parameter_value(n.parameters, "SpringSettings::mStiffness"), s.stiffness / m, 1e-9);
  EXPECT_NEAR(*parameter_value(n.parameters, "SpringSettings::mDamping"), s.damping / m, 1e-12);
  EXPECT_EQ(*f.predicted.frequency_hz, *k.predicted.frequency_hz);
  EXPECT_EQ(*f.predicted.damping_ratio, *n.predicted.damping_ratio);
}

TEST(JoltModel, VelocityAndPositionStepsChangeNothing) {
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 4.0;
  const Target t = target(4.0, 0.2, m, h, spring_constants(m, omega, 0.2));
  SettingValues v = default_settings(kJoltModel);
  const EngineReport a = kJoltModel.report(t, v);
  v[kJoltNumVelocitySteps] = 1;
  v[kJoltNumPositionSteps] = 0;
  const EngineReport b = kJoltModel.report(t, v);
  EXPECT_EQ(*a.predicted.frequency_hz, *b.predicted.frequency_hz);
  EXPECT_EQ(*a.predicted.damping_ratio, *b.predicted.damping_ratio);
}

TEST(JoltModel, DampingThatStopsTheBodyHasNoExact) {
  // mLinearDamping h >= 1 zeroes the velocity every step (max(0, 1 - d h)).
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 2.0;
  const EngineReport r = kJoltModel.report(target(2.0, 0.5, m, h, spring_constants(m, omega, 0.5)), jolt_settings(1, 60.0));
  EXPECT_FALSE(r.exact);
  EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
}

}  // namespace
}  // namespace softtune::engines

namespace softtune::engines {
namespace {

TEST(JoltModel, NoExportBreaksTheEnginesRulesOverASweep) {
  // Every exact export keeps k > 0 and c + h k >= the float margin at the collision step, and meets the
  // request; every plain export either is legal and predicted, or refused with the warning.
  int exact_count = 0, refused = 0, inexact = 0;
  for (double ratio : {0.001, 0.01, 0.1, 0.3}) {
    for (double zeta : {0.0, 1e-4, 0.01, 0.3, 1.0, 2.0}) {
      for (double m : {1e-3, 1.0, 1e3}) {
        for (int n : {1, 2, 7}) {
          for (double d : {0.0, 0.05, 3.0}) {
            for (int mode : {0, 1, 2}) {
              for (bool exact_mode : {false, true}) {
                const double fps = 60.0, h = 1.0 / fps, hz = ratio * fps, omega = 2.0 * kPi * hz;
                const SpringConstants s = exact_mode ? exact_spring(m, omega, zeta, h).spring : spring_constants(m, omega, zeta);
                const EngineReport r = kJoltModel.report(target(hz, zeta, m, h, s), jolt_settings(n, d, mode));
                // A refused export says so first; its prediction is the engine's step with what was typed.
                const bool refuses = !r.warnings.empty() && r.warnings.front().code == WarningCode::engine_refuses;
                if (refuses) ++refused;
                if (!r.predicted.frequency_hz) {
                  EXPECT_TRUE(refuses);
                }
                if (!r.exact) {
                  ++inexact;
                  EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
                  continue;
                }
                ++exact_count;
                const double hs = h / n;
                double k = 0.0, c = 0.0;
                if (mode == 0) {
                  const double w = 2.0 * kPi * *parameter_value(*r.exact, "SpringSettings::mFrequency");
                  k = m * w * w;
                  c = 2.0 * m * *parameter_value(*r.exact, "SpringSettings::mDamping") * w;
                } else {
                  const double scale = mode == 2 ? m : 1.0;
                  k = scale * *parameter_value(*r.exact, "SpringSettings::mStiffness");
                  c = scale * *parameter_value(*r.exact, "SpringSettings::mDamping");
                }
                EXPECT_GT(k, 0.0);
                EXPECT_GE(c + hs * k, kJoltFloatMargin * hs * k) << ratio << " " << zeta << " " << m << " " << n << " " << d;
                const Prediction p = predict_from_step_map(jolt_step_map(m, k, c, h, n, d), h);
                ASSERT_TRUE(p.frequency_hz && p.damping_ratio);
                // The nearest legal value (flagged engine_inexact) within 1 % / 0.02, else the exact bars.
                const bool nearest = !r.warnings.empty() && r.warnings.back().code == WarningCode::engine_inexact;
                EXPECT_NEAR(*p.frequency_hz / hz, 1.0, nearest ? kNearestFrequencyTolerance : kExactFrequencyTolerance);
                EXPECT_NEAR(*p.damping_ratio, zeta, nearest ? kNearestDampingTolerance : kExactDampingTolerance);
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(exact_count, 1000);
  EXPECT_GT(refused, 0);
  EXPECT_GT(inexact, 0);
}

}  // namespace
}  // namespace softtune::engines
