// ODE 0.16's model against ODE's own equations: a literal scalar re-run of dxStepIsland's direct solve and of
// dxQuickStepIsland's SOR sweeps (scaled rows, fc, lambda from 0) for one body on one row, and against closed
// forms: dWorldStep with one row is implicit Euler on k = ERP / (h CFM), c = (1 - ERP) / CFM, and the exact
// parameters put the step's poles at exp(s h).
#include "softtune/engines/ode.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"
#include "softtune/integrators.h"

namespace softtune::engines {
namespace {

using testing::target;

SettingValues quickstep(double iterations, double w) {
  SettingValues v = default_settings(kOdeModel);
  v[kOdeStepper] = 1;
  v[kOdeIterations] = iterations;
  v[kOdeSorW] = w;
  return v;
}

double det(const Eigen::Matrix2d& a) { return a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0); }

struct RowState {
  double x, v;
};

// step.cpp dxStepIsland, written out for one row on a body of mass m held by a static world:
// getInfo2 gives rhs = fps erp (-x) and cfm; Stage2a multiplies both by 1/h; A = J invM J' + cfm/h;
// rhs -= J (v/h + invM fe) with fe = 0; dxSolveLCP on one unbounded row is lambda = rhs / A;
// Stage4: v += h invM J' lambda; dxStepBody: x += h v.
RowState ode_world_step(RowState s, double m, double erp, double cfm, double h) {
  const double fps = 1.0 / h;
  double rhs = fps * erp * (-s.x), row_cfm = cfm;
  rhs *= fps;
  row_cfm *= fps;
  const double a = 1.0 / m + row_cfm;
  rhs -= s.v * fps;
  const double lambda = rhs / a;
  const double v1 = s.v + h * lambda / m;
  return {s.x + h * v1, v1};
}

// quickstep.cpp dxQuickStepIsland, written out for one row: rhs and cfm as above; iMJ = invM J' = 1/m;
// Stage4LCP_AdComputation: Ad = w / (J iMJ + cfm), then cfm, rhs and J are scaled by Ad; each sweep
// (Stage4LCP_IterationStep): delta = rhs - lambda cfm - J fc, lambda += delta (no bounds), fc += delta iMJ;
// Stage5/6: v += h fc; dxStepBody: x += h v.
RowState ode_quick_step(RowState s, double m, double erp, double cfm, double h, int iterations, double w) {
  const double fps = 1.0 / h;
  double rhs = fps * erp * (-s.x) * fps - s.v * fps, row_cfm = cfm * fps, j = 1.0;
  const double imj = 1.0 / m;
  const double ad = w / (j * imj + row_cfm);
  row_cfm *= ad;
  rhs *= ad;
  j *= ad;
  double lambda = 0.0, fc = 0.0;
  for (int i = 0; i < iterations; ++i) {
    const double delta = rhs - lambda * row_cfm - j * fc;
    lambda += delta;
    fc += delta * imj;
  }
  const double v1 = s.v + h * fc;
  return {s.x + h * v1, v1};
}

TEST(OdeModel, WorldStepMapIsODEsDirectSolve) {
  const double m = 2.5, h = 1.0 / 60.0;
  for (double erp : {0.2, 0.8, 1.6}) {
    for (double cfm : {1e-5, 1e-3, 0.1}) {
      const Eigen::Matrix2d a = ode_step_map(m, erp, cfm, h, 1.0);
      for (RowState s0 : {RowState{1.0, 0.0}, RowState{0.0, 1.0}, RowState{0.3, -2.0}}) {
        const RowState s1 = ode_world_step(s0, m, erp, cfm, h);
        EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12 * (1.0 + std::abs(s1.x)));
        EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12 * (1.0 + std::abs(s1.v)));
      }
    }
  }
}

TEST(OdeModel, QuickStepMapIsODEsSorSweeps) {
  const double m = 0.3, h = 1.0 / 120.0, erp = 0.4, cfm = 2e-3;
  for (int iterations : {1, 2, 3, 20}) {
    for (double w : {0.5, 1.0, 1.3, 1.9}) {
      const Eigen::Matrix2d a = ode_step_map(m, erp, cfm, h, ode_impulse_fraction(quickstep(iterations, w)));
      for (RowState s0 : {RowState{1.0, 0.0}, RowState{0.0, 1.0}}) {
        const RowState s1 = ode_quick_step(s0, m, erp, cfm, h, iterations, w);
        EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12 * (1.0 + std::abs(s1.x)));
        EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12 * (1.0 + std::abs(s1.v)));
      }
    }
  }
}

TEST(OdeModel, ImpulseFractionOfTheSteppers) {
  EXPECT_EQ(ode_impulse_fraction(default_settings(kOdeModel)), 1.0);
  EXPECT_NEAR(ode_impulse_fraction(quickstep(20, 1.3)), 1.0 - std::pow(0.3, 20), 1e-15);
  EXPECT_NEAR(ode_impulse_fraction(quickstep(1, 1.3)), 1.3, 1e-15);
  EXPECT_NEAR(ode_impulse_fraction(quickstep(2, 1.3)), 1.0 - 0.09, 1e-15);
  EXPECT_NEAR(ode_impulse_fraction(quickstep(3, 0.5)), 1.0 - 0.125, 1e-15);
}

TEST(OdeModel, WorldStepIsImplicitEulerOnTheUserGuidesSpring) {
  // ERP = h k / (h k + c), CFM = 1 / (h k + c) <=> k = ERP / (h CFM), c = (1 - ERP) / CFM.
  const double m = 3.0, k = 500.0, c = 4.0, h = 1.0 / 60.0;
  const double erp = h * k / (h * k + c), cfm = 1.0 / (h * k + c);
  const Eigen::Matrix2d a = ode_step_map(m, erp, cfm, h, 1.0);
  testing::expect_implicit_euler(a, m, k, c, h);
}

TEST(OdeModel, StandardExportPredictsImplicitEulersPoles) {
  // docs/math.md: asked 10 Hz free at 60 fps, standard softness gives 8.49 Hz natural with zeta 0.416.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 10.0;
  const EngineReport r = kOdeModel.report(target(10.0, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                          default_settings(kOdeModel));
  ASSERT_TRUE(r.predicted.frequency_hz);
  EXPECT_NEAR(*r.predicted.frequency_hz, 8.49, 0.01);
  EXPECT_NEAR(*r.predicted.damping_ratio, 0.416, 0.001);
  // Undamped: ERP = h k / h k = 1, CFM = 1 / (h k).
  EXPECT_NEAR(*parameter_value(r.parameters, "dParamERP"), 1.0, 1e-15);
  EXPECT_NEAR(*parameter_value(r.parameters, "dParamCFM"), 1.0 / (h * m * omega * omega), 1e-15);
}

// The characteristic polynomial of the 2x2 map is z^2 - trace z + det: its poles meet exp(s h) when
// det = P = exp(-2 zeta omega h) and trace = S = 2 exp(-zeta omega h) cos(omega_d h).
void expect_exact_poles(const Parameters& exact, double m, double hz, double zeta, double h, double rho) {
  const double erp = exact[0].value, cfm = exact[1].value, omega = 2.0 * std::numbers::pi * hz;
  const Eigen::Matrix2d a = ode_step_map(m, erp, cfm, h, rho);
  const double e = std::exp(-zeta * omega * h);
  EXPECT_NEAR(det(a), e * e, 1e-10);
  EXPECT_NEAR(a.trace(), 2.0 * e * std::cos(omega * std::sqrt(1.0 - zeta * zeta) * h), 1e-10);
}

TEST(OdeModel, ExactParametersPutThePolesAtExpSh) {
  const double m = 0.5, h = 1.0 / 120.0, hz = 7.0, omega = 2.0 * std::numbers::pi * hz;
  for (const SettingValues& settings : {default_settings(kOdeModel), quickstep(1, 1.3), quickstep(2, 1.3),
                                        quickstep(20, 1.3), quickstep(4, 0.8)}) {
    const double rho = ode_impulse_fraction(settings);
    for (double zeta : {0.05, 0.3, 0.9}) {
      const ExactSpring closed = exact_spring(m, omega, zeta, h);
      const EngineReport r = kOdeModel.report(target(hz, zeta, m, h, closed.spring), settings);
      ASSERT_TRUE(r.exact && r.exact_predicted) << zeta << " " << rho;
      expect_exact_poles(*r.exact, m, hz, zeta, h, rho);
      EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-8 * hz);
      EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 1e-8);
      // ERP does not depend on the stepper: it is exact softness's beta'.
      EXPECT_NEAR((*r.exact)[0].value, closed.softness.beta, 1e-9 * std::abs(closed.softness.beta));
    }
  }
}

TEST(OdeModel, ExactOfTheWorldStepIsTheExactSoftSpring) {
  // With rho = 1, ERP and CFM are exact mode's k', c' through the user guide's formulas.
  const double m = 4.0, h = 1.0 / 60.0, hz = 3.0, zeta = 0.2, omega = 2.0 * std::numbers::pi * hz;
  const ExactSpring closed = exact_spring(m, omega, zeta, h);
  const EngineReport r = kOdeModel.report(target(hz, zeta, m, h, closed.spring), default_settings(kOdeModel));
  ASSERT_TRUE(r.exact);
  const double d = h * closed.spring.stiffness + closed.spring.damping;
  EXPECT_NEAR(*parameter_value(*r.exact, "dParamERP"), h * closed.spring.stiffness / d, 1e-9);
  EXPECT_NEAR(*parameter_value(*r.exact, "dParamCFM"), 1.0 / d, 1e-9 / d);
  // And the plain export of k', c' is the same row, predicted exact.
  EXPECT_NEAR(*r.predicted.frequency_hz, hz, 1e-8);
  EXPECT_NEAR(*r.predicted.damping_ratio, zeta, 1e-8);
}

TEST(OdeModel, LightDampingNeedsErpAboveOneWhichOdeTakes) {
  // c' < 0 below zeta = omega h / 2 (about): ERP = h k' / (h k' + c') > 1, taken as typed by ODE.
  const double m = 1.0, h = 1.0 / 60.0, hz = 10.0, zeta = 0.1;
  const EngineReport r = kOdeModel.report(target(hz, zeta, m, h, spring_constants(m, 2 * std::numbers::pi * hz, zeta)),
                                          default_settings(kOdeModel));
  ASSERT_TRUE(r.exact);
  EXPECT_GT((*r.exact)[0].value, 1.0);
  expect_exact_poles(*r.exact, m, hz, zeta, h, 1.0);
}

TEST(OdeModel, ZeroDampingIsMetWithinTheToleranceAtTheFloor) {
  const double m = 1.0, h = 1.0 / 60.0, hz = 10.0;
  for (const SettingValues& settings : {default_settings(kOdeModel), quickstep(1, 1.3)}) {
    const EngineReport r = kOdeModel.report(target(hz, 0.0, m, h, spring_constants(m, 2 * std::numbers::pi * hz, 0.0)),
                                            settings);
    ASSERT_TRUE(r.exact && r.exact_predicted);
    EXPECT_NEAR(*r.exact_predicted->damping_ratio, kOdeDampingFloor, 1e-9);
    EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-8 * hz);
    EXPECT_GT((*r.exact)[1].value, 0.0);
    EXPECT_LE((*r.exact)[0].value, kOdeMaxErp);
  }
}

TEST(OdeModel, ExactModesUndampedSpringIsRefusedNotExported) {
  // Exact mode at zeta = 0 gives c' = -h k': h k' + c' = 0, so CFM = 1 / 0.
  const double m = 1.0, h = 1.0 / 60.0, k = 1000.0;
  const EngineReport r = kOdeModel.report(target(5.0, 0.0, m, h, {k, -h * k}), default_settings(kOdeModel));
  EXPECT_TRUE(r.parameters.empty());
  EXPECT_FALSE(r.predicted.frequency_hz);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
  // A spring whose c + h k is a rounding remainder would need ERP above the ceiling: refused too.
  const EngineReport tiny = kOdeModel.report(target(5.0, 0.0, m, h, {k, -h * k * (1.0 - 1e-9)}),
                                             default_settings(kOdeModel));
  EXPECT_TRUE(tiny.parameters.empty());
  EXPECT_EQ(tiny.warnings[0].code, WarningCode::engine_refuses);
}

TEST(OdeModel, UnderRelaxedSweepsCannotDampHeavilyAndSaySo) {
  // One sweep at w = 0.5 applies half the impulse: G < 0.5, so det = 1 - G > 0.5, while zeta = 2 at
  // 0.2 f/fps needs P = exp(-2 zeta omega h) = 0.0066 (slow pole alone: far below 0.5).
  const double m = 1.0, h = 1.0 / 60.0, hz = 12.0, zeta = 2.0;
  const double omega = 2.0 * std::numbers::pi * hz;
  const EngineReport r = kOdeModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)), quickstep(1, 0.5));
  EXPECT_FALSE(r.exact);
  bool inexact = false;
  for (const Warning& w : r.warnings) inexact = inexact || w.code == WarningCode::engine_inexact;
  EXPECT_TRUE(inexact);
}

TEST(OdeModel, OneOverRelaxedSweepCanBlowUpAndIsFlagged) {
  // One sweep at w = 1.9: G = 1.9 h / (h + m CFM) near 1.9 for a stiff row: the velocity flips sign and grows.
  const double m = 1.0, h = 1.0 / 60.0, hz = 15.0, zeta = 1.0, omega = 2.0 * std::numbers::pi * hz;
  const EngineReport r = kOdeModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)), quickstep(1, 1.9));
  const Eigen::Matrix2d a = ode_step_map(m, r.parameters[0].value, r.parameters[1].value, h, 1.9);
  const std::complex<double> disc = std::sqrt(std::complex<double>(a.trace() * a.trace() - 4.0 * det(a)));
  const double radius = std::max(std::abs(0.5 * (a.trace() + disc)), std::abs(0.5 * (a.trace() - disc)));
  EXPECT_NEAR(r.predicted.spectral_radius, radius, 1e-12);
  EXPECT_EQ(r.predicted.stable, radius <= 1.0 + 1e-9);
  if (!r.predicted.stable) {
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_EQ(r.warnings[0].code, WarningCode::engine_unstable);
  }
}

TEST(OdeModel, NeverExportsOutsideTheLegalRanges) {
  // Whatever is asked, every exported ERP is in (0, kOdeMaxErp] and every CFM positive and finite, and an
  // `exact` meets the request as predicted.
  int exported = 0;
  for (const SettingValues& settings : {default_settings(kOdeModel), quickstep(1, 1.3), quickstep(2, 0.3),
                                        quickstep(20, 1.9)}) {
    for (double hz : {0.1, 3.0, 40.0, 1000.0}) {
      for (double zeta : {0.0, 1e-3, 0.3, 1.0, 5.0, 50.0}) {
        for (double m : {1e-6, 1.0, 1e6}) {
          for (double h : {1.0 / 30.0, 1.0 / 240.0, 1.0 / 2000.0}) {
            const double omega = 2.0 * std::numbers::pi * hz;
            for (SpringConstants spring : {spring_constants(m, omega, zeta), exact_spring(m, omega, zeta, h).spring}) {
              const EngineReport r = kOdeModel.report(target(hz, zeta, m, h, spring), settings);
              for (const std::optional<Parameters>& p : {std::optional<Parameters>(r.parameters), r.exact}) {
                if (!p || p->empty()) continue;
                ++exported;
                EXPECT_GT((*p)[0].value, 0.0);
                EXPECT_LE((*p)[0].value, kOdeMaxErp);
                EXPECT_GT((*p)[1].value, 0.0);
                EXPECT_TRUE(std::isfinite((*p)[1].value));
              }
              if (r.exact) {
                ASSERT_TRUE(r.exact_predicted && r.exact_predicted->frequency_hz);
                EXPECT_NEAR(*r.exact_predicted->frequency_hz / hz, 1.0, kExactFrequencyTolerance);
                EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, kExactDampingTolerance);
              }
            }
          }
        }
      }
    }
  }
  EXPECT_GT(exported, 1000);
}

}  // namespace
}  // namespace softtune::engines
