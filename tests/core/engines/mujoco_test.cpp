// MuJoCo's model against MuJoCo's own equations (engine_core_constraint.c mj_makeImpedance, getsolparam;
// engine_forward.c mj_Euler, mj_RungeKutta) and closed forms. The real engine runs the same cases in
// tests/engines/mujoco.
#include "softtune/engines/mujoco.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

using testing::kPi;

using testing::target;

SettingValues mujoco_settings(MujocoIntegrator integrator = MujocoIntegrator::euler) {
  SettingValues v = default_settings(kMujocoModel);
  v[kMujocoIntegrator] = static_cast<double>(integrator);
  return v;
}

// One step of a = -beta v - kappa r as MuJoCo's Euler takes it (mj_advance): velocity first, then position
// with the new velocity.
Eigen::Vector2d euler_step(Eigen::Vector2d s, double beta, double kappa, double h) {
  const double v1 = s(1) + h * (-beta * s(1) - kappa * s(0));
  return {s(0) + h * v1, v1};
}

// Classic RK4 on (r' = v, v' = -beta v - kappa r), stage by stage as mj_RungeKutta does.
Eigen::Vector2d rk4_step(Eigen::Vector2d s, double beta, double kappa, double h) {
  auto f = [&](Eigen::Vector2d x) { return Eigen::Vector2d(x(1), -beta * x(1) - kappa * x(0)); };
  const Eigen::Vector2d k1 = f(s), k2 = f(s + 0.5 * h * k1), k3 = f(s + 0.5 * h * k2), k4 = f(s + h * k3);
  return s + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// The eigenvalues of the map MuJoCo steps with the exported solref, against exp(s h) of the request.
void expect_poles_match(const Parameters& p, MujocoIntegrator integrator, double omega, double zeta, double h) {
  const double s0 = *parameter_value(p, "solref[0]"), s1 = *parameter_value(p, "solref[1]");
  const double d = *parameter_value(p, "solimp[1]");
  EXPECT_EQ(*parameter_value(p, "solimp[0]"), d);  // flat: getimpedance returns d whatever the violation
  EXPECT_FALSE((s0 > 0.0) != (s1 > 0.0)) << "mixed solref " << s0 << " " << s1;
  if (s0 > 0.0) {
    EXPECT_GE(s0, 2.0 * h);  // the 2h floor would change it
  }
  const MujocoGains g = mujoco_gains(s0, s1, d, d, h, true);
  EXPECT_FALSE(g.replaced_by_default || g.floored);
  Eigen::EigenSolver<Eigen::Matrix2d> es(mujoco_step_map(integrator, g.beta, g.kappa, h));
  std::complex<double> z = es.eigenvalues()(0);
  if (z.imag() < 0.0) z = std::conj(z);
  const std::complex<double> want = std::exp(
      h * (zeta < 1.0 ? std::complex<double>(-zeta * omega, omega * std::sqrt(1.0 - zeta * zeta))
                      : std::complex<double>(-omega * (zeta - std::sqrt(zeta * zeta - 1.0)), 0.0)));
  const std::complex<double> other = es.eigenvalues()(1);
  const double err = std::min(std::abs(z - want), std::abs(other - want));
  EXPECT_LT(err, 1e-6) << "poles " << z << " " << other << " want " << want;
}

TEST(MujocoModel, SettingsAreMujocosDefaultsAndClamps) {
  const SettingValues v = default_settings(kMujocoModel);
  ASSERT_EQ(v.size(), static_cast<std::size_t>(kMujocoSettingCount));
  // mj_defaultSolRefImp: solimp 0.9 0.95 0.001 0.5 2; mj_defaultOption: integrator Euler, refsafe on.
  EXPECT_EQ(v[kMujocoIntegrator], 0.0);
  EXPECT_EQ(v[kMujocoSolimp0], 0.9);
  EXPECT_EQ(v[kMujocoSolimp1], 0.95);
  EXPECT_EQ(v[kMujocoSolimp2], 0.001);
  EXPECT_EQ(v[kMujocoSolimp3], 0.5);
  EXPECT_EQ(v[kMujocoSolimp4], 2.0);
  EXPECT_EQ(v[kMujocoRefsafe], 0.0);
  // getsolparam clamps solimp[0], [1], [3] to [mjMINIMP, mjMAXIMP], width to >= 0, power to >= 1: the
  // legal ranges are exactly what MuJoCo leaves untouched.
  for (int i : {kMujocoSolimp0, kMujocoSolimp1, kMujocoSolimp3}) {
    EXPECT_EQ(kMujocoModel.settings[i].min, 0.0001);
    EXPECT_EQ(kMujocoModel.settings[i].max, 0.9999);
  }
  EXPECT_EQ(kMujocoModel.settings[kMujocoSolimp2].min, 0.0);
  EXPECT_EQ(kMujocoModel.settings[kMujocoSolimp4].min, 1.0);
  EXPECT_EQ(kMujocoModel.settings[kMujocoIntegrator].choices.size(), 4u);
}

TEST(MujocoModel, GainsAreMakeImpedancesKAndBTimesTheImpedance) {
  const double h = 0.002;
  // Standard, flat at dmax: K d^2 = 1 / (timeconst dampratio)^2, B d = 2 / timeconst, for any d.
  for (double d : {0.95, 0.5, 0.9999}) {
    const MujocoGains g = mujoco_gains(0.05, 0.3, d, d, h, true);
    EXPECT_NEAR(g.kappa, 1.0 / (0.05 * 0.05 * 0.3 * 0.3), 1e-9);
    EXPECT_NEAR(g.beta, 2.0 / 0.05, 1e-12);
  }
  // Direct: K = -solref[0] / dmax^2, B = -solref[1] / dmax; at imp = dmax, a = solref[1] v + solref[0] r.
  const MujocoGains direct = mujoco_gains(-400.0, -3.0, 0.95, 0.95, h, true);
  EXPECT_NEAR(direct.kappa, 400.0, 1e-9);
  EXPECT_NEAR(direct.beta, 3.0, 1e-12);
  // Another impedance than dmax scales B by imp / dmax and K by (imp / dmax)^2.
  const MujocoGains low = mujoco_gains(-400.0, -3.0, 0.9, 0.95, h, true);
  EXPECT_NEAR(low.kappa, 400.0 * (0.9 / 0.95) * (0.9 / 0.95), 1e-9);
  EXPECT_NEAR(low.beta, 3.0 * 0.9 / 0.95, 1e-12);
}

TEST(MujocoModel, MixedSolrefIsTheDefaultAndTheFloorIsTwoSteps) {
  const double h = 1.0 / 60.0;
  // getsolparam: (solref[0] > 0) ^ (solref[1] > 0) -> (0.02, 1), then the 2h floor: 0.02 < 2/60.
  for (auto [s0, s1] : {std::pair{-100.0, 2.0}, std::pair{0.1, 0.0}, std::pair{0.1, -1.0}}) {
    const MujocoGains g = mujoco_gains(s0, s1, 0.95, 0.95, h, true);
    EXPECT_TRUE(g.replaced_by_default);
    EXPECT_TRUE(g.floored);
    EXPECT_NEAR(g.timeconst_used, 2.0 * h, 1e-15);
    EXPECT_NEAR(g.beta, 2.0 / (2.0 * h), 1e-9);
  }
  // Direct (-k, 0) is not mixed: both are <= 0.
  EXPECT_FALSE(mujoco_gains(-100.0, 0.0, 0.95, 0.95, h, true).replaced_by_default);
  // refsafe disabled (mjDSBL_REFSAFE): the timeconst is kept.
  const MujocoGains kept = mujoco_gains(0.01, 1.0, 0.95, 0.95, h, false);
  EXPECT_FALSE(kept.floored);
  EXPECT_NEAR(kept.beta, 200.0, 1e-9);
  EXPECT_TRUE(mujoco_gains(0.01, 1.0, 0.95, 0.95, h, true).floored);
}

TEST(MujocoModel, StepMapsAreSemiImplicitEulerAndRk4) {
  const double beta = 3.0, kappa = 900.0, h = 1.0 / 120.0;
  for (Eigen::Vector2d s0 : {Eigen::Vector2d(1.0, 0.0), Eigen::Vector2d(0.0, 1.0), Eigen::Vector2d(0.3, -2.0)}) {
    for (MujocoIntegrator i : {MujocoIntegrator::euler, MujocoIntegrator::implicit, MujocoIntegrator::implicitfast}) {
      const Eigen::Vector2d got = mujoco_step_map(i, beta, kappa, h) * s0;
      EXPECT_LT((got - euler_step(s0, beta, kappa, h)).norm(), 1e-13);
    }
    const Eigen::Vector2d rk = mujoco_step_map(MujocoIntegrator::rk4, beta, kappa, h) * s0;
    EXPECT_LT((rk - rk4_step(s0, beta, kappa, h)).norm(), 1e-13);
  }
}

TEST(MujocoModel, StandardExportOfAnUndampedSpringIsDirectAndSymplectic) {
  // 10 Hz undamped at 60 fps: the export is direct (-omega^2, 0); semi-implicit Euler keeps it undamped,
  // at cos(theta) = 1 - (omega h)^2 / 2 (not implicit Euler's 8.49 Hz, zeta 0.416).
  const double m = 2.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 10.0;
  const EngineReport r =
      kMujocoModel.report(target(10.0, 0.0, m, h, spring_constants(m, omega, 0.0)), mujoco_settings());
  EXPECT_NEAR(*parameter_value(r.parameters, "solref[0]"), -omega * omega, 1e-9);
  EXPECT_EQ(*parameter_value(r.parameters, "solref[1]"), 0.0);
  EXPECT_EQ(*parameter_value(r.parameters, "solimp[0]"), 0.95);
  ASSERT_TRUE(r.predicted.frequency_hz);
  const double theta = std::acos(1.0 - 0.5 * omega * omega * h * h);
  EXPECT_NEAR(*r.predicted.frequency_hz, theta / (2.0 * kPi * h), 1e-9);
  EXPECT_NEAR(*r.predicted.damping_ratio, 0.0, 1e-9);
  EXPECT_TRUE(r.warnings.empty());
  ASSERT_TRUE(r.exact);
  expect_poles_match(*r.exact, MujocoIntegrator::euler, omega, 0.0, h);
}

TEST(MujocoModel, StandardExportOfADampedSpringIsTimeconstAndDampratio) {
  const double m = 0.01, h = 1.0 / 240.0, omega = 2.0 * kPi * 5.0, zeta = 0.4;
  const EngineReport r =
      kMujocoModel.report(target(5.0, zeta, m, h, spring_constants(m, omega, zeta)), mujoco_settings());
  EXPECT_NEAR(*parameter_value(r.parameters, "solref[0]"), 1.0 / (zeta * omega), 1e-12);
  EXPECT_NEAR(*parameter_value(r.parameters, "solref[1]"), zeta, 1e-12);
  // Semi-implicit Euler's poles for beta = 2 zeta omega, kappa = omega^2: z^2 - (2 - hb - h^2 k) z + 1 - hb.
  const double b = 2.0 * zeta * omega, k = omega * omega;
  const double p = 1.0 - h * b, s = 2.0 - h * b - h * h * k;
  const std::complex<double> z = 0.5 * (s + std::sqrt(std::complex<double>(s * s - 4.0 * p)));
  const std::complex<double> sc = std::log(z) / h;
  EXPECT_NEAR(*r.predicted.frequency_hz, std::abs(sc) / (2.0 * kPi), 1e-9);
  EXPECT_NEAR(*r.predicted.damping_ratio, -sc.real() / std::abs(sc), 1e-9);
}

TEST(MujocoModel, ExactIsTheSemiImplicitEulerClosedForm) {
  for (double zeta : {0.0, 0.05, 0.3, 1.0, 2.0}) {
    for (double fh : {0.01, 0.1, 0.3}) {
      const double h = 1.0 / 100.0, hz = fh / h, omega = 2.0 * kPi * hz, m = 5.0;
      for (MujocoIntegrator i : {MujocoIntegrator::euler, MujocoIntegrator::implicit}) {
        const EngineReport r = kMujocoModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)),
                                                   mujoco_settings(i));
        ASSERT_TRUE(r.exact && r.exact_predicted) << zeta << " " << fh;
        expect_poles_match(*r.exact, i, omega, zeta, h);
        EXPECT_NEAR(*r.exact_predicted->frequency_hz / hz, 1.0, 1e-9);
        EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 1e-9);
        // Closed form: h beta = 1 - exp(-2 zeta omega h); standard form's timeconst = 2 / beta > 2h.
        const double s0 = *parameter_value(*r.exact, "solref[0]");
        if (zeta > 0.0) {
          EXPECT_NEAR(s0, 2.0 * h / -std::expm1(-2.0 * zeta * omega * h), 1e-9 * s0);
        } else {
          EXPECT_LT(s0, 0.0);
          EXPECT_EQ(*parameter_value(*r.exact, "solref[1]"), 0.0);
        }
      }
    }
  }
}

TEST(MujocoModel, Rk4ExactMatchesWhereSolrefCanDampAndSaysWhereNot) {
  const double h = 1.0 / 60.0, m = 1.0;
  // (Over-damped poles below RK4's real minimum T4(-1.6) = 0.27 have no real RK4 root: kept out here.)
  for (auto [zeta, fh] : {std::pair{0.2, 0.2}, std::pair{0.7, 0.2}, std::pair{1.5, 0.05}}) {
    const double hz = fh / h, omega = 2.0 * kPi * hz;
    const EngineReport r = kMujocoModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)),
                                               mujoco_settings(MujocoIntegrator::rk4));
    ASSERT_TRUE(r.exact) << zeta;
    expect_poles_match(*r.exact, MujocoIntegrator::rk4, omega, zeta, h);
  }
  // Undamped at omega h = 1.9: RK4's own damping there (|T4(i 1.9)| < 1) exceeds the tolerance, and
  // cancelling it needs negative damping.
  const double hz = 1.9 / (2.0 * kPi * h), omega = 2.0 * kPi * hz;
  const EngineReport r = kMujocoModel.report(target(hz, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                             mujoco_settings(MujocoIntegrator::rk4));
  EXPECT_FALSE(r.exact);
  bool inexact = false;
  for (const Warning& w : r.warnings) inexact |= w.code == WarningCode::engine_inexact && w.engine == "mujoco";
  EXPECT_TRUE(inexact);
}

TEST(MujocoModel, ExactModesNegativeDampingIsReportedAsReplaced) {
  // softtune's exact spring at zeta = 0 has c' = -h k' < 0: direct solref (-k'/m, -c'/m) mixes signs and
  // MuJoCo uses (0.02, 1), floored to 2h at 60 fps.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 5.0;
  const ExactSpring ex = exact_spring(m, omega, 0.0, h);
  const EngineReport r = kMujocoModel.report(target(5.0, 0.0, m, h, ex.spring), mujoco_settings());
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
  // What it then does: timeconst 2h, dampratio 1: beta = 1 / h, kappa = 1 / (2h)^2.
  const Prediction want = predict_from_step_map(
      mujoco_step_map(MujocoIntegrator::euler, 1.0 / h, 1.0 / (4.0 * h * h), h), h);
  EXPECT_NEAR(r.predicted.spectral_radius, want.spectral_radius, 1e-12);
  ASSERT_TRUE(r.exact);
  expect_poles_match(*r.exact, MujocoIntegrator::euler, omega, 0.0, h);
}

TEST(MujocoModel, DirectExportOfAStiffDampedSpringIsUnstable) {
  // zeta = 1 at 0.3 fps: timeconst 1 / (zeta omega) < 2h, so the export is direct, and h B = 2 zeta omega h
  // = 3.8 > 2: MuJoCo's explicit constraint force diverges (the NaN of the issue).
  const double m = 1.0, h = 1.0 / 60.0, hz = 0.3 / h, omega = 2.0 * kPi * hz;
  const EngineReport r =
      kMujocoModel.report(target(hz, 1.0, m, h, spring_constants(m, omega, 1.0)), mujoco_settings());
  EXPECT_LT(*parameter_value(r.parameters, "solref[0]"), 0.0);
  EXPECT_FALSE(r.predicted.stable);
  bool unstable = false;
  for (const Warning& w : r.warnings) unstable |= w.code == WarningCode::engine_unstable;
  EXPECT_TRUE(unstable);
  ASSERT_TRUE(r.exact);
  expect_poles_match(*r.exact, MujocoIntegrator::euler, omega, 1.0, h);
}

TEST(MujocoModel, AnyFlatImpedanceGivesTheSameResponse) {
  // K and B are divided by dmax = solimp[1], and the flat impedance is solimp[1]: the solref means the same
  // spring whatever d_width the user keeps.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * kPi * 4.0, zeta = 0.3;
  const Target t = target(4.0, zeta, m, h, spring_constants(m, omega, zeta));
  const EngineReport base = kMujocoModel.report(t, mujoco_settings());
  for (double d : {0.0001, 0.5, 0.9999}) {
    SettingValues v = mujoco_settings();
    v[kMujocoSolimp1] = d;
    const EngineReport r = kMujocoModel.report(t, v);
    EXPECT_EQ(*parameter_value(r.parameters, "solimp[0]"), d);
    EXPECT_EQ(*parameter_value(r.parameters, "solimp[1]"), d);
    EXPECT_NEAR(*r.predicted.frequency_hz, *base.predicted.frequency_hz, 1e-9);
    EXPECT_NEAR(*r.predicted.damping_ratio, *base.predicted.damping_ratio, 1e-9);
    ASSERT_TRUE(r.exact);
    EXPECT_NEAR(*parameter_value(*r.exact, "solref[0]"), *parameter_value(*base.exact, "solref[0]"), 1e-12);
  }
}

TEST(MujocoModel, DiagRatioIsTheSolversRealisedFraction) {
  // One row: J a = (A D aref) / (1 + A D), D = imp / ((1 - imp) diagApprox), A = rho diagApprox.
  const double h = 0.01, d = 0.95, rho = 3.0;
  const MujocoGains g = mujoco_gains(-400.0, -3.0, d, d, h, true, rho);
  const double ad = rho * d / (1.0 - d);
  EXPECT_NEAR(g.beta, ad / (1.0 + ad) * 3.0 / d, 1e-12);
  EXPECT_NEAR(g.kappa, ad / (1.0 + ad) * d * 400.0 / (d * d), 1e-9);
  // The exact solref compensates it: the map MuJoCo steps has the request's poles.
  const double m = 1.0, hz = 3.0, omega = 2.0 * kPi * hz, zeta = 0.2;
  SettingValues v = mujoco_settings();
  v[kMujocoDiagRatio] = rho;
  const Target t = target(hz, zeta, m, h, spring_constants(m, omega, zeta));
  const EngineReport r = kMujocoModel.report(t, v), base = kMujocoModel.report(t, mujoco_settings());
  ASSERT_TRUE(r.exact && base.exact);
  auto gains_of = [&](const Parameters& p, double ratio) {
    return mujoco_gains(*parameter_value(p, "solref[0]"), *parameter_value(p, "solref[1]"), d, d, h, true, ratio);
  };
  // The same gains (and so the same motion) as the exact solref of a row whose diagonal is exact.
  const MujocoGains ge = gains_of(*r.exact, rho), want_e = gains_of(*base.exact, 1.0);
  EXPECT_NEAR(ge.beta, want_e.beta, 1e-9 * want_e.beta);
  EXPECT_NEAR(ge.kappa, want_e.kappa, 1e-9 * want_e.kappa);
  // And the plain export, typed as is, is stiffer than asked by g / d.
  EXPECT_GT(*r.predicted.frequency_hz, *base.predicted.frequency_hz);
}

TEST(MujocoModel, NoSpringIsAZeroDirectSolref) {
  const EngineReport r = kMujocoModel.report(target(0.0, 0.0, 1.0, 1.0 / 60.0, {0.0, 0.0}), mujoco_settings());
  EXPECT_FALSE(std::signbit(*parameter_value(r.parameters, "solref[0]")));
  EXPECT_FALSE(std::signbit(*parameter_value(r.parameters, "solref[1]")));
  EXPECT_FALSE(r.exact);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(MujocoModel, ExactNeverExportsWhatMujocoReplaces) {
  for (MujocoIntegrator i : {MujocoIntegrator::euler, MujocoIntegrator::rk4}) {
    for (double zeta : {0.0, 0.01, 0.5, 1.0, 2.0}) {
      for (double fh : {0.001, 0.05, 0.15, 0.3}) {
        for (int substeps : {1, 8}) {
          const double h = 1.0 / (60.0 * substeps), hz = fh * 60.0, omega = 2.0 * kPi * hz;
          const EngineReport r = kMujocoModel.report(
              target(hz, zeta, 1.0, h, spring_constants(1.0, omega, zeta)), mujoco_settings(i));
          if (!r.exact) continue;
          const double s0 = *parameter_value(*r.exact, "solref[0]"), s1 = *parameter_value(*r.exact, "solref[1]");
          EXPECT_FALSE((s0 > 0.0) != (s1 > 0.0));
          if (s0 > 0.0) {
            EXPECT_GE(s0, 2.0 * h);
          }
          EXPECT_TRUE(std::isfinite(s0) && std::isfinite(s1));
        }
      }
    }
  }
}

}  // namespace
}  // namespace softtune::engines
