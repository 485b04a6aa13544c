// Rapier's model against the engine's own equations (motor_model.rs combine_coefficients,
// joint_velocity_constraint.rs solve_generic, the staged solver's substep loop): one world step of dt runs
// num_solver_iterations substeps of dt / n, each the soft motor row, which is implicit Euler on
// (m_eff, k_f, c_f); exact parameters are softtune's exact spring at the substep.
#include "softtune/engines/rapier.h"

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

SettingValues rapier_settings(int iterations, int model = 0, double damping = 0.0) {
  SettingValues v = default_settings(kRapierModel);
  v[kRapierNumSolverIterations] = iterations;
  v[kRapierMotorModel] = model;
  v[kRapierLinearDamping] = damping;
  return v;
}

// One solve_generic of the motor row from zero impulse, as motor_model.rs and finalize_constraints build it
// (body 2 dynamic with dot_jj = 1/m, body 1 fixed; u = J v2 with v2 -= im2 J delta).
State motor_substep(State s, double m, double stiffness, double damping, bool acceleration, double h) {
  const double erp_inv_dt = stiffness / (h * stiffness + damping);
  const double inv = 1.0 / (h * h * stiffness + h * damping);
  const double dot_jj = 1.0 / m;
  const double cfm_gain = acceleration ? dot_jj * inv : inv;
  const double inv_lhs = 1.0 / (dot_jj + cfm_gain);
  const double rhs = s.v + s.x * erp_inv_dt;
  double impulse = inv_lhs * rhs;          // pass with bias, from impulse 0
  double v = s.v - dot_jj * impulse;
  const double x = s.x + h * v;            // integrate positions
  const double delta = inv_lhs * (v + s.x * erp_inv_dt - cfm_gain * impulse);  // unbiased pass: same rhs
  impulse += delta;
  v -= dot_jj * delta;
  return {x, v};
}

TEST(RapierModel, DefaultsAreTheEngines) {
  const SettingValues d = default_settings(kRapierModel);
  EXPECT_EQ(d[kRapierNumSolverIterations], 4);  // IntegrationParameters::default
  EXPECT_EQ(d[kRapierNumInternalPgsIterations], 1);
  EXPECT_EQ(d[kRapierMotorModel], 0);           // MotorModel::AccelerationBased
  EXPECT_EQ(d[kRapierAdditionalSolverIterations], 0);
  EXPECT_EQ(d[kRapierLinearDamping], 0.0);
}

TEST(RapierModel, StepMapIsTheMotorRowPerSubstep) {
  const double m = 3.0, k = 500.0, c = 4.0, dt = 1.0 / 60.0;
  for (int n : {1, 4, 7}) {
    const Eigen::Matrix2d a = rapier_step_map(m, k, c, dt, n, 0.0);
    for (bool acceleration : {false, true}) {
      for (State s0 : {State{1.0, 0.0}, State{0.0, 1.0}, State{0.3, -2.0}}) {
        State s = s0, ie = s0;
        for (int i = 0; i < n; ++i) {
          s = acceleration ? motor_substep(s, m, k / m, c / m, true, dt / n) : motor_substep(s, m, k, c, false, dt / n);
          ie = implicit_euler_step(ie, Oscillator{m, k, c}, dt / n);
        }
        EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s.x, 1e-12);
        EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s.v, 1e-12);
        EXPECT_NEAR(s.x, ie.x, 1e-12);
      }
    }
  }
  // apply_damping at writeback: v /= 1 + dt d once per step.
  const Eigen::Matrix2d d = rapier_step_map(m, k, c, dt, 4, 2.0);
  const Eigen::Matrix2d u = rapier_step_map(m, k, c, dt, 4, 0.0);
  EXPECT_NEAR(d(1, 0), u(1, 0) / (1.0 + dt * 2.0), 1e-12);
  EXPECT_NEAR(d(0, 1), u(0, 1), 1e-15);
}

TEST(RapierModel, SolverIterationsAreSubsteps) {
  // The issue: the plain export is right only when softtune is told substeps: 4. At fps 60 the default
  // Rapier step is implicit Euler at 1/240 with the same k, c.
  const double m = 1.0, hz = 10.0, omega = 2.0 * kPi * hz;
  const SpringConstants s = spring_constants(m, omega, 0.0);
  const EngineReport r = kRapierModel.report(target(hz, 0.0, m, 1.0 / 60.0, s), default_settings(kRapierModel));
  const EngineReport one = kRapierModel.report(target(hz, 0.0, m, 1.0 / 240.0, s), rapier_settings(1));
  ASSERT_TRUE(r.predicted.frequency_hz && one.predicted.frequency_hz);
  EXPECT_NEAR(*r.predicted.frequency_hz, *one.predicted.frequency_hz, 1e-9);
  EXPECT_NEAR(*r.predicted.damping_ratio, *one.predicted.damping_ratio, 1e-9);
  // ...and with numSolverIterations 1 it is softtune's standard prediction at 60 fps: 8.49 Hz, 0.416.
  const EngineReport single = kRapierModel.report(target(hz, 0.0, m, 1.0 / 60.0, s), rapier_settings(1));
  EXPECT_NEAR(*single.predicted.frequency_hz, 8.49, 0.01);
  EXPECT_NEAR(*single.predicted.damping_ratio, 0.416, 0.001);
}

TEST(RapierModel, MotorModelsTypeTheSameSpring) {
  const double m = 5.0, h = 1.0 / 60.0, hz = 2.0, zeta = 0.4, omega = 2.0 * kPi * hz;
  const SpringConstants s = spring_constants(m, omega, zeta);
  const EngineReport a = kRapierModel.report(target(hz, zeta, m, h, s), rapier_settings(4, 0));
  const EngineReport f = kRapierModel.report(target(hz, zeta, m, h, s), rapier_settings(4, 1));
  EXPECT_EQ(a.parameters[0].choice, "AccelerationBased");
  EXPECT_NEAR(*parameter_value(a.parameters, "JointMotor::stiffness"), omega * omega, 1e-9);
  EXPECT_NEAR(*parameter_value(a.parameters, "JointMotor::damping"), 2.0 * zeta * omega, 1e-12);
  EXPECT_EQ(f.parameters[0].choice, "ForceBased");
  EXPECT_NEAR(*parameter_value(f.parameters, "JointMotor::stiffness"), s.stiffness, 1e-9);
  EXPECT_NEAR(*f.predicted.frequency_hz, *a.predicted.frequency_hz, 1e-12);
}

TEST(RapierModel, ExactIsTheExactSpringAtTheSubstep) {
  const double m = 0.5, dt = 1.0 / 60.0;
  for (int n : {1, 4, 8}) {
    for (double zeta : {0.05, 0.7, 2.0}) {
      const double hz = 9.0, omega = 2.0 * kPi * hz;
      const EngineReport r = kRapierModel.report(target(hz, zeta, m, dt, spring_constants(m, omega, zeta)), rapier_settings(n, 1));
      ASSERT_TRUE(r.exact && r.exact_predicted) << n << " " << zeta;
      const ExactSpring e = exact_spring(m, omega, zeta, dt / n);
      EXPECT_NEAR(*parameter_value(*r.exact, "JointMotor::stiffness"), e.spring.stiffness, 1e-12 * e.spring.stiffness);
      EXPECT_NEAR(*parameter_value(*r.exact, "JointMotor::damping"), e.spring.damping, 1e-9 * std::abs(e.spring.damping) + 1e-12);
      EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-9 * hz);
      EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 1e-9);
      const Prediction p = predict_from_step_map(
          rapier_step_map(m, *parameter_value(*r.exact, "JointMotor::stiffness"),
                          *parameter_value(*r.exact, "JointMotor::damping"), dt, n, 0.0), dt);
      EXPECT_NEAR(*p.frequency_hz, hz, 1e-9 * hz);
      EXPECT_NEAR(*p.damping_ratio, zeta, 1e-9);
      EXPECT_NEAR(p.spectral_radius, r.exact_predicted->spectral_radius, 1e-12);
    }
  }
}

TEST(RapierModel, ExactUndampedStaysClearOfTheLock) {
  const double m = 2.0, dt = 1.0 / 60.0, hz = 6.0, omega = 2.0 * kPi * hz;
  const EngineReport r = kRapierModel.report(target(hz, 0.0, m, dt, spring_constants(m, omega, 0.0)),
                                             default_settings(kRapierModel));
  ASSERT_TRUE(r.exact && r.exact_predicted);
  const double h = dt / 4, k = *parameter_value(*r.exact, "JointMotor::stiffness") * m;
  const double c = *parameter_value(*r.exact, "JointMotor::damping") * m;
  EXPECT_GE(c + h * k, kRapierFloatMargin * h * k);
  EXPECT_LE(*r.exact_predicted->damping_ratio, kExactDampingTolerance);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, hz * kExactFrequencyTolerance);
}

TEST(RapierModel, SoftExactExportAtTheFrameStepIsRefusedAndPredicted) {
  // softtune's exact mode at zeta = 0 for h = 1/60 gives c' = -h k'; Rapier's substep is h / 4, so
  // h^2 k + h c < 0 at its substep: a negative compliance, whose algebra is implicit Euler at h / 4 with the
  // negative damping: per substep det = m / (m + hs c + hs^2 k), a complex pair of modulus sqrt(det), so
  // per step (4 substeps) the spectral radius is det^2 > 1.
  const double m = 1.0, h = 1.0 / 60.0, k = 1000.0;
  const EngineReport r = kRapierModel.report(target(5.0, 0.0, m, h, {k, -h * k}), default_settings(kRapierModel));
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
  EXPECT_EQ(r.warnings[0].engine, "rapier");
  const double hs = h / 4.0, det = m / (m - hs * h * k + hs * hs * k);
  EXPECT_FALSE(r.predicted.stable);
  EXPECT_NEAR(r.predicted.spectral_radius, det * det, 1e-6);  // the model steps the f32 h and k
  // At one iteration and h = 1/64, k = 1024, c = -16 both f32 sums are exactly 0: utils::inv gives 0, the
  // motor's cfm and erp vanish and the first pass zeroes the velocity: the stretch holds (rigid).
  testing::expect_refused_and_held(kRapierModel.report(target(5.0, 0.0, m, 1.0 / 64.0, {1024.0, -16.0}), rapier_settings(1)));
}

TEST(RapierModel, LinearDampingIsCompensatedBySolving) {
  const double m = 1.0, dt = 1.0 / 60.0, hz = 3.0, zeta = 0.2, omega = 2.0 * kPi * hz;
  const EngineReport r = kRapierModel.report(target(hz, zeta, m, dt, spring_constants(m, omega, zeta)), rapier_settings(4, 0, 0.5));
  ASSERT_TRUE(r.exact && r.exact_predicted);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, hz * kExactFrequencyTolerance);
  EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, kExactDampingTolerance);
  // Undamped cannot be reached through the damping at a low frequency: the nearest is reported.
  const double slow = 2.0 * kPi * 0.5;
  const EngineReport u = kRapierModel.report(target(0.5, 0.0, m, dt, spring_constants(m, slow, 0.0)), rapier_settings(4, 0, 0.5));
  EXPECT_FALSE(u.exact);
  EXPECT_EQ(u.warnings.back().code, WarningCode::engine_inexact);
}

}  // namespace
}  // namespace softtune::engines

namespace softtune::engines {
namespace {

TEST(RapierModel, NoExportBreaksTheEnginesRulesOverASweep) {
  int exact_count = 0, refused = 0;
  for (double ratio : {0.001, 0.01, 0.1, 0.3}) {
    for (double zeta : {0.0, 1e-4, 0.01, 0.3, 1.0, 2.0}) {
      for (double m : {1e-3, 1.0, 1e3}) {
        for (int n : {1, 4, 9}) {
          for (double d : {0.0, 0.2}) {
            for (int model : {0, 1}) {
              for (bool exact_mode : {false, true}) {
                const double fps = 60.0, h = 1.0 / fps, hz = ratio * fps, omega = 2.0 * kPi * hz;
                const SpringConstants s = exact_mode ? exact_spring(m, omega, zeta, h).spring : spring_constants(m, omega, zeta);
                const EngineReport r = kRapierModel.report(target(hz, zeta, m, h, s), rapier_settings(n, model, d));
                // A refused export says so first; its prediction is the engine's step with what was typed.
                const bool refuses = !r.warnings.empty() && r.warnings.front().code == WarningCode::engine_refuses;
                if (refuses) ++refused;
                if (!r.predicted.frequency_hz) {
                  EXPECT_TRUE(refuses);
                }
                if (!r.exact) {
                  EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
                  continue;
                }
                ++exact_count;
                const double scale = model == 0 ? m : 1.0, hs = h / n;
                const double k = scale * *parameter_value(*r.exact, "JointMotor::stiffness");
                const double c = scale * *parameter_value(*r.exact, "JointMotor::damping");
                EXPECT_GT(k, 0.0);
                EXPECT_GE(c + hs * k, kRapierFloatMargin * hs * k) << ratio << " " << zeta << " " << m << " " << n;
                const Prediction p = predict_from_step_map(rapier_step_map(m, k, c, h, n, d), h);
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
  EXPECT_GT(exact_count, 500);
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace softtune::engines
