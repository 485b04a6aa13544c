// Bullet 3.24's model against the engine's own equations and closed forms: the spring2 row is
// semi-implicit Euler on the body mass, the ERP/CFM row is n Gauss-Seidel sweeps of
// lambda = rhs - CFM lambda, and the exact parameters put the step's poles at exp(s h).
#include "softtune/engines/bullet.h"

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

SettingValues bullet_settings(double route, int iterations) {
  SettingValues v = default_settings(kBulletModel);
  v[kBulletRouteSetting] = route;
  v[kBulletIterationsSetting] = iterations;
  return v;
}

std::string_view choice_of(const Parameters& ps, std::string_view name) {
  for (const Parameter& p : ps) {
    if (p.name == name) return p.choice;
  }
  return {};
}

bool has_warning(const EngineReport& r, WarningCode code) {
  for (const Warning& w : r.warnings) {
    if (w.code == code && w.engine == kBulletModel.name && !w.detail.empty()) return true;
  }
  return false;
}

// The solver's row as resolveSingleConstraintRowGeneric runs it, for one body of effective mass m on a static
// ground: deltaImpulse = rhs - lambda cfm - (J dv) m, with J dv = lambda / m after the impulses so far.
double row_velocity_change(double m, double rhs_velocity, double cfm, int iterations) {
  const double rhs = rhs_velocity * m;  // m_rhs = (constraint error - rel_vel) m_jacDiagABInv
  double lambda = 0.0, dv = 0.0;
  for (int j = 0; j < iterations; ++j) {
    const double delta = rhs - lambda * cfm - dv * m;
    lambda += delta;
    dv += delta / m;
  }
  return dv;
}

TEST(BulletModel, DefaultsAreBulletsOwn) {
  const SettingValues v = default_settings(kBulletModel);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[kBulletRouteSetting], kBulletRouteSpring2);  // what a user reaches for: the spring
  EXPECT_EQ(v[kBulletIterationsSetting], 10.0);            // btContactSolverInfo: m_numIterations = 10
  EXPECT_EQ(kBulletModel.settings[kBulletIterationsSetting].name, "m_numIterations");
}

TEST(BulletModel, Spring2StepIsSemiImplicitEulerOnTheBodyMass) {
  const double body_mass = 2.0, k = 300.0, c = 3.0, h = 1.0 / 90.0;
  const Eigen::Matrix2d a = bullet_spring2_step_map(body_mass, k, c, h);
  for (State s0 : {State{1.0, 0.0}, State{0.0, 1.0}, State{0.2, -1.5}}) {
    const State s1 = semi_implicit_euler_step(s0, Oscillator{body_mass, k, c}, h);
    EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12);
    EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12);
  }
}

TEST(BulletModel, SpringLimitsAreGetLimitMotorInfo2s) {
  const double m = 4.0, h = 0.01;
  // sqrt(k / m) h = 0.2 <= 0.25: kept; 0.3: replaced by m / (16 h^2).
  EXPECT_FALSE(bullet_spring_in_use(m, m * 400.0, 0.0, h, true, true).stiffness_limited);
  const BulletSpringInUse over = bullet_spring_in_use(m, m * 900.0, 0.0, h, true, true);
  EXPECT_TRUE(over.stiffness_limited);
  EXPECT_DOUBLE_EQ(over.stiffness, m / (16.0 * h * h));
  EXPECT_FALSE(bullet_spring_in_use(m, m * 900.0, 0.0, h, false, true).stiffness_limited);
  // c h > m: replaced by m / h.
  const BulletSpringInUse damped = bullet_spring_in_use(m, 0.0, 500.0, h, true, true);
  EXPECT_TRUE(damped.damping_limited);
  EXPECT_DOUBLE_EQ(damped.damping, m / h);
  EXPECT_FALSE(bullet_spring_in_use(m, 0.0, 300.0, h, true, true).damping_limited);
}

TEST(BulletModel, CfmGainIsTheSolversIteration) {
  const double m = 0.7, rhs_velocity = 1.3;
  for (int n : {1, 2, 3, 4, 10, 25}) {
    for (double cfm : {0.0, 0.3, 0.9, 1.0, 1.4, 5.0}) {
      const double dv = row_velocity_change(m, rhs_velocity, cfm, n);
      EXPECT_NEAR(bullet_cfm_gain(cfm, n) * rhs_velocity, dv, 1e-9 * std::max(1.0, std::abs(dv)))
          << n << " " << cfm;
    }
  }
  EXPECT_DOUBLE_EQ(bullet_cfm_gain(0.8, 1), 1.0);             // one sweep ignores the CFM
  EXPECT_NEAR(bullet_cfm_gain(0.5, 200), 1.0 / 1.5, 1e-15);   // converged: 1 / (1 + CFM)
  EXPECT_LT(bullet_cfm_gain(1.2, 10), -1.0);                  // CFM above 1: the sweeps diverge
}

TEST(BulletModel, ConvergedErpCfmIsImplicitEulerWithBulletsCfm) {
  // Bullet's CFM = m / (h (h k + c)) is ODE's CFM h / m_eff; below 1 and converged it is implicit Euler.
  const double m = 1.0, h = 1.0 / 60.0, k = 8000.0, c = 40.0;
  const double erp = h * k / (h * k + c), cfm = m / (h * (h * k + c));
  ASSERT_LT(cfm, 1.0);
  const Eigen::Matrix2d a = bullet_erp_cfm_step_map(erp, cfm, 1000, h);
  for (State s0 : {State{1.0, 0.0}, State{0.0, 1.0}, State{-0.4, 2.0}}) {
    const State s1 = implicit_euler_step(s0, Oscillator{m, k, c}, h);
    EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12);
    EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12);
  }
}

TEST(BulletModel, CfmForGainInvertsTheGain) {
  for (int n : {2, 4, 10, 3, 5, 11}) {
    for (double g : {1.0, 0.9, 0.8, 0.5, 0.1, 1e-3, 1e-6}) {
      const std::optional<double> cfm = bullet_cfm_for_gain(g, n);
      // An odd count has a least gain: min over c of (1 + c^n) / (1 + c); n = 3 gives 3/4.
      if (n == 3 && g < 0.75) {
        EXPECT_FALSE(cfm) << n << " " << g;
        continue;
      }
      if (!cfm) {
        EXPECT_EQ(n % 2, 1) << n << " " << g;
        continue;
      }
      EXPECT_GE(*cfm, 0.0);
      EXPECT_LT(*cfm, 1.0);
      EXPECT_NEAR(bullet_cfm_gain(*cfm, n), g, 1e-12) << n << " " << g;
    }
  }
  EXPECT_FALSE(bullet_cfm_for_gain(0.5, 1));
  EXPECT_FALSE(bullet_cfm_for_gain(0.0, 10));
  EXPECT_FALSE(bullet_cfm_for_gain(1.2, 10));
  EXPECT_TRUE(bullet_cfm_for_gain(0.8, 3));  // 1 - c + c^2 = 0.8 at c = 0.276
  EXPECT_NEAR(*bullet_cfm_for_gain(0.8, 3), (1.0 - std::sqrt(0.2)) / 2.0, 1e-12);
}

TEST(BulletModel, Spring2PlainExportPredictsSemiImplicitEuler) {
  // 2 Hz, zeta 0.3 at 60 Hz: within the stiffness limit, so the prediction is semi-implicit Euler on (k, c).
  const double m = 1.5, h = 1.0 / 60.0, omega = 2.0 * kPi * 2.0;
  const SpringConstants s = spring_constants(m, omega, 0.3);
  const EngineReport r = kBulletModel.report(target(2.0, 0.3, m, h, s), default_settings(kBulletModel));
  EXPECT_EQ(choice_of(r.parameters, kBulletStiffnessLimit), kBulletTrue);
  EXPECT_NEAR(*parameter_value(r.parameters, kBulletStiffness), s.stiffness, 1e-6 * s.stiffness);
  // Semi-implicit Euler's poles: det = 1 - h c / m, trace = 2 - h (h k + c) / m.
  const double det = 1.0 - h * s.damping / m, trace = 2.0 - h * (h * s.stiffness + s.damping) / m;
  const double r2 = det, cos_theta = trace / (2.0 * std::sqrt(det));
  const double sigma = -std::log(r2) / (2.0 * h), wd = std::acos(cos_theta) / h;
  ASSERT_TRUE(r.predicted.frequency_hz && r.predicted.damping_ratio);
  EXPECT_NEAR(*r.predicted.frequency_hz, std::hypot(sigma, wd) / (2.0 * kPi), 1e-5);
  EXPECT_NEAR(*r.predicted.damping_ratio, sigma / std::hypot(sigma, wd), 1e-6);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(BulletModel, Spring2LimitIsReportedAndItsFrequencyPredicted) {
  // 15 Hz undamped at 60 Hz: sqrt(k / m) h = 1.57 > 0.25, so Bullet springs at h^2 k / m = 1 / 16, i.e.
  // 2 - 1/16 = 2 cos(theta): natural frequency theta / (2 pi h), undamped.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 15.0;
  const EngineReport r = kBulletModel.report(target(15.0, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                             default_settings(kBulletModel));
  EXPECT_TRUE(has_warning(r, WarningCode::engine_refuses));
  ASSERT_TRUE(r.predicted.frequency_hz);
  EXPECT_NEAR(*r.predicted.frequency_hz, std::acos(1.0 - 1.0 / 32.0) / (2.0 * kPi * h), 1e-4);
  EXPECT_NEAR(*r.predicted.damping_ratio, 0.0, 1e-9);
  // Exact: limitIfNeeded off, k = 4 m sin^2(omega h / 2) / h^2 (the symplectic spring), c = 0.
  ASSERT_TRUE(r.exact && r.exact_predicted);
  EXPECT_EQ(choice_of(*r.exact, kBulletStiffnessLimit), kBulletFalse);
  const double k = 4.0 * m * std::pow(std::sin(omega * h / 2.0), 2) / (h * h);
  EXPECT_NEAR(*parameter_value(*r.exact, kBulletStiffness), k, 1e-6 * k);
  EXPECT_EQ(*parameter_value(*r.exact, kBulletDamping), 0.0);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, 15.0, 15.0 * kExactFrequencyTolerance);
}

TEST(BulletModel, Spring2ExactMeetsEveryRequestInReach) {
  for (double m : {1e-3, 1.0, 1e3}) {
    for (double h : {1.0 / 60.0, 1.0 / 480.0}) {
      for (double f_per_step : {0.005, 0.05, 0.3}) {
        for (double zeta : {0.0, 0.2, 1.0, 2.0}) {
          const double hz = f_per_step / h, omega = 2.0 * kPi * hz;
          const EngineReport r = kBulletModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)),
                                                     default_settings(kBulletModel));
          ASSERT_TRUE(r.exact && r.exact_predicted) << m << " " << h << " " << f_per_step << " " << zeta;
          EXPECT_NEAR(*r.exact_predicted->frequency_hz / hz, 1.0, kExactFrequencyTolerance);
          EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, kExactDampingTolerance);
          // c = m (1 - exp(-2 zeta omega h)) / h: never negative, never above Bullet's m / h limit.
          const double c = *parameter_value(*r.exact, kBulletDamping);
          EXPECT_NEAR(c, -m * std::expm1(-2.0 * zeta * omega * h) / h, 1e-6 * m / h);
          EXPECT_GE(c, 0.0);
          EXPECT_LT(c * h, m);
        }
      }
    }
  }
}

TEST(BulletModel, Spring2UsesTheBodyMassNotTheEffectiveMass) {
  // An anchor off the centre: m_eff = 1 but Bullet's spring divides by the body's 2 kg, so the typed
  // spring acts at half strength and the exact stiffness is twice the point body's.
  const double h = 1.0 / 60.0, omega = 2.0 * kPi * 1.0;
  Target point = target(1.0, 0.1, 1.0, h, spring_constants(1.0, omega, 0.1));
  Target plank = point;
  plank.box2d_reduced_mass = 2.0;
  const EngineReport rp = kBulletModel.report(point, default_settings(kBulletModel));
  const EngineReport rb = kBulletModel.report(plank, default_settings(kBulletModel));
  ASSERT_TRUE(rp.exact && rb.exact);
  EXPECT_NEAR(*parameter_value(*rb.exact, kBulletStiffness), 2.0 * *parameter_value(*rp.exact, kBulletStiffness),
              1e-6);
  EXPECT_NEAR(*rb.predicted.frequency_hz, *rp.predicted.frequency_hz / std::sqrt(2.0), 0.01);
}

TEST(BulletModel, Spring2PlainExactModeSpringWithNegativeDampingIsUnstable) {
  // Exact mode at zeta 0 hands over implicit Euler's c' = -h k': explicit in Bullet, it grows.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 3.0;
  const ExactSpring e = exact_spring(m, omega, 0.0, h);
  const EngineReport r = kBulletModel.report(target(3.0, 0.0, m, h, e.spring), default_settings(kBulletModel));
  EXPECT_FALSE(r.predicted.stable);
  EXPECT_TRUE(has_warning(r, WarningCode::engine_unstable));
  ASSERT_TRUE(r.exact);
  EXPECT_NEAR(*r.exact_predicted->damping_ratio, 0.0, kExactDampingTolerance);
}

TEST(BulletModel, ErpCfmOldExportIsNotBulletsConvention) {
  // softtune's old export, CFM = 1 / (h k + c), on a 1 g body at 1 Hz: the CFM is far above 1 and ten sweeps
  // diverge (the 0 of 60).
  const double m = 1e-3, h = 1.0 / 60.0, omega = 2.0 * kPi;
  const SpringConstants s = spring_constants(m, omega, 0.5);
  const EngineReport r = kBulletModel.report(target(1.0, 0.5, m, h, s), bullet_settings(kBulletRouteErpCfm, 10));
  EXPECT_NEAR(*parameter_value(r.parameters, kBulletStopCfm), 1.0 / (h * s.stiffness + s.damping), 1e-3);
  EXPECT_FALSE(r.predicted.stable);
  EXPECT_TRUE(has_warning(r, WarningCode::engine_unstable));
  EXPECT_TRUE(has_warning(r, WarningCode::engine_refuses));  // CFM >= 1 is outside the legal range
  // Exact: Bullet's own convention, inside the legal ranges.
  ASSERT_TRUE(r.exact && r.exact_predicted);
  const double erp = *parameter_value(*r.exact, kBulletStopErp), cfm = *parameter_value(*r.exact, kBulletStopCfm);
  EXPECT_GT(erp, 0.0);
  EXPECT_LE(erp, 1.0);
  EXPECT_GE(cfm, 0.0);
  EXPECT_LT(cfm, 1.0);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, 1.0, kExactFrequencyTolerance);
  EXPECT_NEAR(*r.exact_predicted->damping_ratio, 0.5, kExactDampingTolerance);
}

TEST(BulletModel, ErpCfmExactIsTheClosedForm) {
  // g = 1 - P, ERP = (1 - z1)(1 - z2) / (1 - P), and g_n(CFM) = g, for a damping the route can hold.
  const double m = 2.0, h = 1.0 / 120.0, hz = 4.0, zeta = 0.7, omega = 2.0 * kPi * hz;
  for (int n : {4, 10, 40}) {
    const EngineReport r = kBulletModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)),
                                               bullet_settings(kBulletRouteErpCfm, n));
    ASSERT_TRUE(r.exact) << n;
    const double e = std::exp(-zeta * omega * h), theta = omega * h * std::sqrt(1.0 - zeta * zeta);
    const double p = e * e, sum = 2.0 * e * std::cos(theta);
    const double erp = (1.0 + p - sum) / (1.0 - p);
    EXPECT_NEAR(*parameter_value(*r.exact, kBulletStopErp), erp, 1e-6 * erp);
    const double cfm = *parameter_value(*r.exact, kBulletStopCfm);
    EXPECT_NEAR(bullet_cfm_gain(cfm, n), 1.0 - p, 1e-6);
  }
}

TEST(BulletModel, ErpCfmCannotHoldLittleDamping) {
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 5.0;
  // Undamped: g = 0 needs CFM = 1.
  EngineReport r = kBulletModel.report(target(5.0, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                       bullet_settings(kBulletRouteErpCfm, 10));
  EXPECT_FALSE(r.exact);
  EXPECT_TRUE(has_warning(r, WarningCode::engine_inexact));
  // zeta 0.05 at omega h = 0.52: its exact damping is negative, ERP would exceed 1.
  r = kBulletModel.report(target(5.0, 0.05, m, h, spring_constants(m, omega, 0.05)),
                          bullet_settings(kBulletRouteErpCfm, 10));
  EXPECT_FALSE(r.exact);
  EXPECT_TRUE(has_warning(r, WarningCode::engine_inexact));
  // One sweep ignores the CFM: only g = 1 is reachable.
  r = kBulletModel.report(target(5.0, 0.7, m, h, spring_constants(m, omega, 0.7)),
                          bullet_settings(kBulletRouteErpCfm, 1));
  EXPECT_FALSE(r.exact);
  EXPECT_TRUE(has_warning(r, WarningCode::engine_inexact));
}

TEST(BulletModel, ErpCfmNeverExportsOutsideItsRange) {
  for (int n : {2, 3, 10}) {
    for (double zeta : {0.0, 0.01, 0.1, 0.5, 1.0, 2.0}) {
      for (double hz : {0.5, 5.0, 18.0}) {
        const double m = 3.0, h = 1.0 / 60.0, omega = 2.0 * kPi * hz;
        const EngineReport r = kBulletModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)),
                                                   bullet_settings(kBulletRouteErpCfm, n));
        if (!r.exact) {
          EXPECT_TRUE(has_warning(r, WarningCode::engine_inexact));
          continue;
        }
        const double erp = *parameter_value(*r.exact, kBulletStopErp), cfm = *parameter_value(*r.exact, kBulletStopCfm);
        EXPECT_GT(erp, 0.0);
        EXPECT_LE(erp, 1.0);
        EXPECT_GE(cfm, 0.0);
        EXPECT_LT(cfm, 1.0);
        EXPECT_TRUE(r.exact_predicted->stable);
      }
    }
  }
}

TEST(BulletModel, ErpCfmPlainExportOutsideTheRangeIsFlagged) {
  // Exact mode at zeta 0.02: c' < 0, so the old export's ERP = h k' / (h k' + c') is above 1.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 5.0;
  const ExactSpring e = exact_spring(m, omega, 0.02, h);
  ASSERT_LT(e.spring.damping, 0.0);
  const EngineReport r = kBulletModel.report(target(5.0, 0.02, m, h, e.spring), bullet_settings(kBulletRouteErpCfm, 10));
  EXPECT_GT(*parameter_value(r.parameters, kBulletStopErp), 1.0);
  EXPECT_TRUE(has_warning(r, WarningCode::engine_refuses));
}

TEST(BulletModel, ZeroDenominatorIsRefusedNotDivided) {
  const double h = 1.0 / 60.0;
  const EngineReport r = kBulletModel.report(target(5.0, 0.0, 1.0, h, {600.0, -600.0 * h}),
                                             bullet_settings(kBulletRouteErpCfm, 10));
  EXPECT_TRUE(has_warning(r, WarningCode::engine_refuses));
  EXPECT_FALSE(r.predicted.frequency_hz);
}

}  // namespace
}  // namespace softtune::engines
