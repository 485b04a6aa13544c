// PhysX 5's drive model against PhysX's own equations (PhysX does not install here): a literal scalar re-run,
// for one body on one D6 drive row, of the PGS loop (compute1dConstraintSolverConstantsPGS, solve1D over the
// position and velocity iterations, conclude1D, integrateCore) and of the TGS loop
// (compute1dConstraintSolverConstantsTGS, solve1DStep per position iteration with integrateBodies(stepDt),
// conclude1DStep, velocity iterations), and against closed forms: PGS is one implicit-Euler step, TGS
// positionIterations of them at dt / positionIterations, an acceleration drive the same on unit mass.
#include "softtune/engines/physx.h"

#include "engine_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"
#include "softtune/integrators.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"

namespace softtune::engines {
namespace {

constexpr double kFltMax = 3.4028234663852886e38;

using testing::target;

SettingValues physx_settings(double solver, double position, double velocity, double drive) {
  return {solver, position, velocity, drive};
}

template <typename Real>
struct RowT {
  Real x, v;
};
using Row = RowT<double>;

// PGS, one body of mass m on a static world, one drive row J = 1 with geometric error C = x (the drive pulls
// by F = -k C - d J v, Px1DConstraint's spring convention), forceLimit PX_MAX_F32.
template <typename Real>
RowT<Real> pgs_simulate(RowT<Real> s, Real m, Real k, Real d, Real dt, int position_iterations,
                        int velocity_iterations, bool acceleration) {
  const Real flt_max = static_cast<Real>(kFltMax);
  // DyConstraintSetup.cpp setupSolverConstraint: unitResponse r = J M^-1 J^T, initJointSpeed = J v.
  const Real r = Real(1) / m, recip_r = m, init_joint_speed = s.v, geometric_error = s.x, velocity_target = 0;
  // compute1dConstraintSolverConstantsPGS, eSPRING branch.
  const Real a = dt * dt * k + dt * d;
  const Real b = dt * (d * velocity_target - k * geometric_error);
  Real constant, unbiased_constant, vel_multiplier, impulse_multiplier;
  if (acceleration) {
    const Real x = Real(1) / (Real(1) + a);
    constant = x * recip_r * b;
    vel_multiplier = -x * recip_r * a;
    impulse_multiplier = Real(1) - x;
  } else {
    const Real x = Real(1) / (Real(1) + a * r);
    constant = x * b;
    vel_multiplier = -x * a;
    impulse_multiplier = Real(1) - x;
  }
  unbiased_constant = constant;
  constant += init_joint_speed * vel_multiplier;
  unbiased_constant += init_joint_speed * vel_multiplier;
  // DySolverConstraints.cpp solve1D on a solver body that starts at zero delta velocity.
  Real dv = 0, applied_force = 0;
  auto solve = [&] {
    const Real normal_vel = dv;
    const Real unclamped = impulse_multiplier * applied_force + vel_multiplier * normal_vel + constant;
    const Real clamped = std::min(flt_max, std::max(-flt_max, unclamped));
    const Real delta_f = clamped - applied_force;
    applied_force = clamped;
    dv += delta_f * r;
  };
  for (int i = 0; i < position_iterations; ++i) solve();
  constant = unbiased_constant;  // conclude1D
  for (int i = 0; i < velocity_iterations; ++i) solve();
  // DyBodyCoreIntegrator.h integrateCore: v = v + dv, p += v dt.
  const Real v1 = s.v + dv;
  return {s.x + v1 * dt, v1};
}

// TGS: stepDt = dt / posIters (DyTGSDynamics.cpp); the solver bodies carry full velocities and the motion
// accumulated since the start of the solver (deltaLinDt).
template <typename Real>
RowT<Real> tgs_simulate(RowT<Real> s, Real m, Real k, Real d, Real dt, int position_iterations,
                        int velocity_iterations, bool acceleration) {
  const Real flt_max = static_cast<Real>(kFltMax);
  const Real step_dt = dt / static_cast<Real>(position_iterations);
  const Real r = Real(1) / m, recip_r = m, init_joint_speed = 0, velocity_target = 0;
  // compute1dConstraintSolverConstantsTGS, eSPRING branch.
  const Real a = step_dt * (step_dt * k + d);
  const Real b = step_dt * (d * velocity_target);
  Real bias_scale, error, vel_multiplier, target_vel;
  if (acceleration) {
    const Real x = Real(1) / (Real(1) + a);
    bias_scale = -x * k * step_dt * recip_r;
    vel_multiplier = -x * a * recip_r;
    target_vel = x * b * recip_r - vel_multiplier * init_joint_speed;
  } else {
    const Real x = Real(1) / (Real(1) + a * r);
    bias_scale = -x * k * step_dt;
    vel_multiplier = -x * a;
    target_vel = x * b - vel_multiplier * init_joint_speed;
  }
  error = bias_scale * s.x;
  Real v = s.v, delta_lin = 0, applied_force = 0, elapsed = 0;
  // DyTGSContactPrep.cpp solve1DStep: the spring's resolved error is the motion alone.
  auto solve = [&] {
    const Real error_change = delta_lin;
    const Real bias = error + bias_scale * error_change;
    const Real constant = bias + target_vel;
    const Real unclamped = applied_force + vel_multiplier * v + constant;
    const Real clamped = std::min(flt_max, std::max(-flt_max, unclamped));
    const Real delta_f = clamped - applied_force;
    applied_force = clamped;
    v += delta_f * r;
  };
  for (int i = 0; i < position_iterations; ++i) {
    solve();
    delta_lin += v * step_dt;  // integrateBodies(stepDt)
    elapsed += step_dt;
  }
  // conclude1DStep: a spring row applies zero impulse in the velocity iterations.
  vel_multiplier = 0;
  bias_scale = 0;
  error = 0;
  target_vel = 0;
  for (int i = 0; i < velocity_iterations; ++i) solve();
  return {s.x + delta_lin, v};
}

void expect_map_matches(const Eigen::Matrix2d& a, Row s0, Row s1) {
  EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12 * (1.0 + std::abs(s1.x)));
  EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12 * (1.0 + std::abs(s1.v)));
}

TEST(PhysxModel, PgsMapIsThePgsLoopWhateverTheIterations) {
  const double m = 2.0, k = 800.0, d = 3.0, dt = 1.0 / 60.0;
  for (int position : {1, 4, 32}) {
    for (int velocity : {0, 1, 8}) {
      for (bool acceleration : {false, true}) {
        const Eigen::Matrix2d a = physx_step_map(acceleration ? 1.0 : m, k, d, dt, 1);
        for (Row s0 : {Row{1.0, 0.0}, Row{0.0, 1.0}, Row{0.4, -3.0}}) {
          expect_map_matches(a, s0, pgs_simulate<double>(s0, m, k, d, dt, position, velocity, acceleration));
        }
      }
    }
  }
}

TEST(PhysxModel, TgsMapIsTheTgsLoop) {
  const double m = 0.7, k = 300.0, d = 0.5, dt = 1.0 / 30.0;
  for (int position : {1, 4, 9, 255}) {
    for (int velocity : {0, 1, 4}) {
      for (bool acceleration : {false, true}) {
        const Eigen::Matrix2d a = physx_step_map(acceleration ? 1.0 : m, k, d, dt, position);
        for (Row s0 : {Row{1.0, 0.0}, Row{0.0, 1.0}}) {
          expect_map_matches(a, s0, tgs_simulate<double>(s0, m, k, d, dt, position, velocity, acceleration));
        }
      }
    }
  }
}

TEST(PhysxModel, SubstepsAreOneForPgsAndThePositionIterationsForTgs) {
  EXPECT_EQ(physx_substeps(default_settings(kPhysxModel)), 1);
  EXPECT_EQ(physx_substeps(physx_settings(0, 17, 1, 0)), 1);
  EXPECT_EQ(physx_substeps(physx_settings(1, 4, 1, 0)), 4);
  EXPECT_EQ(physx_substeps(physx_settings(1, 255, 0, 1)), 255);
  // The defaults: PGS, 4 position and 1 velocity iteration, a force drive.
  EXPECT_EQ(default_settings(kPhysxModel), (SettingValues{0, 4, 1, 0}));
}

TEST(PhysxModel, PgsForceDriveIsImplicitEuler) {
  const double m = 3.0, k = 500.0, d = 4.0, h = 1.0 / 60.0;
  const Eigen::Matrix2d a = physx_step_map(m, k, d, h, 1);
  for (State s0 : {State{1.0, 0.0}, State{0.0, 1.0}, State{0.3, -2.0}}) {
    const State s1 = implicit_euler_step(s0, Oscillator{m, k, d}, h);
    EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12);
    EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12);
  }
}

TEST(PhysxModel, TgsIsImplicitEulerAtTheSubstep) {
  const double m = 1.5, k = 2000.0, d = 1.0, h = 1.0 / 60.0;
  const Eigen::Matrix2d a = physx_step_map(m, k, d, h, 4);
  State s{1.0, 0.5};
  const State s0 = s;
  for (int i = 0; i < 4; ++i) s = implicit_euler_step(s, Oscillator{m, k, d}, h / 4);
  EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s.x, 1e-12);
  EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s.v, 1e-12);
}

TEST(PhysxModel, StandardExportPredictsImplicitEulersPoles) {
  // docs/math.md: asked 10 Hz free at 60 fps, standard softness gives 8.49 Hz natural with zeta 0.416.
  const double m = 1.0, h = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 10.0;
  const EngineReport r = kPhysxModel.report(target(10.0, 0.0, m, h, spring_constants(m, omega, 0.0)),
                                            default_settings(kPhysxModel));
  ASSERT_TRUE(r.predicted.frequency_hz);
  EXPECT_NEAR(*r.predicted.frequency_hz, 8.49, 0.01);
  EXPECT_NEAR(*r.predicted.damping_ratio, 0.416, 0.001);
  EXPECT_EQ(*parameter_value(r.parameters, "PxD6JointDrive::stiffness"), m * omega * omega);
  EXPECT_EQ(r.parameters[2].choice, "false");
}

TEST(PhysxModel, AccelerationDriveIsMassFree) {
  // The acceleration drive exports k / m and d / m and predicts the same for any mass.
  const double h = 1.0 / 60.0, hz = 4.0, zeta = 0.3, omega = 2.0 * std::numbers::pi * hz;
  const SettingValues acc = physx_settings(0, 4, 1, 1);
  const EngineReport light = kPhysxModel.report(target(hz, zeta, 0.01, h, spring_constants(0.01, omega, zeta)), acc);
  const EngineReport heavy = kPhysxModel.report(target(hz, zeta, 500.0, h, spring_constants(500.0, omega, zeta)), acc);
  EXPECT_NEAR(light.parameters[0].value, omega * omega, 1e-9 * omega * omega);
  EXPECT_NEAR(light.parameters[1].value, 2.0 * zeta * omega, 1e-12);
  EXPECT_EQ(light.parameters[2].choice, "true");
  EXPECT_NEAR(*light.predicted.frequency_hz, *heavy.predicted.frequency_hz, 1e-9);
  EXPECT_NEAR(*light.predicted.damping_ratio, *heavy.predicted.damping_ratio, 1e-12);
}

// The frame's poles are exp(s dt) when det = exp(-2 zeta omega dt) and trace = 2 e cos(omega_d dt).
void expect_exact_poles(const Parameters& exact, double m, double hz, double zeta, double dt, int n) {
  const double omega = 2.0 * std::numbers::pi * hz;
  const Eigen::Matrix2d a = physx_step_map(m, exact[0].value, exact[1].value, dt, n);
  const double e = std::exp(-zeta * omega * dt);
  EXPECT_NEAR(a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0), e * e, 1e-9);
  EXPECT_NEAR(a.trace(), 2.0 * e * std::cos(omega * std::sqrt(1.0 - zeta * zeta) * dt), 1e-9);
}

TEST(PhysxModel, ExactIsTheExactSpringAtTheSubstep) {
  const double m = 0.5, h = 1.0 / 60.0, hz = 6.0, omega = 2.0 * std::numbers::pi * hz;
  for (int n : {1, 4, 16}) {
    for (double zeta : {0.7, 1.0, 1.8}) {
      const SettingValues s = physx_settings(n == 1 ? 0 : 1, n, 1, 0);
      const EngineReport r = kPhysxModel.report(target(hz, zeta, m, h, spring_constants(m, omega, zeta)), s);
      ASSERT_TRUE(r.exact && r.exact_predicted) << n << " " << zeta;
      const ExactSpring closed = exact_spring(m, omega, zeta, h / n);
      EXPECT_NEAR((*r.exact)[0].value, closed.spring.stiffness, 1e-9 * closed.spring.stiffness);
      EXPECT_NEAR((*r.exact)[1].value, closed.spring.damping, 1e-9 * std::abs(closed.spring.damping) + 1e-12);
      if (zeta < 1.0) expect_exact_poles(*r.exact, m, hz, zeta, h, n);
      EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-7 * hz);
      EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, 1e-7);
    }
  }
}

TEST(PhysxModel, LightDampingNeedsNegativeDampingWhichPhysxRefuses) {
  // PGS at 10 Hz / 60 fps: exact softness needs c' < 0 below zeta ~ omega h / 2 = 0.52.
  const double m = 1.0, h = 1.0 / 60.0, hz = 10.0, zeta = 0.1, omega = 2.0 * std::numbers::pi * hz;
  const ExactSpring closed = exact_spring(m, omega, zeta, h);
  ASSERT_LT(closed.spring.damping, 0.0);
  const EngineReport r = kPhysxModel.report(target(hz, zeta, m, h, closed.spring), default_settings(kPhysxModel));
  // The plain export of exact mode's k', c' is refused, not exported.
  EXPECT_TRUE(r.parameters.empty());
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
  // And no drive meets the request: the nearest is undamped, at the asked frequency, with implicit Euler's
  // own damping: for d = 0 the poles are (1 +- i q) / (1 + q^2), zeta = ln(1 + q^2) / (2 |s| h).
  EXPECT_FALSE(r.exact);
  ASSERT_EQ(r.warnings.size(), 2u);
  EXPECT_EQ(r.warnings[1].code, WarningCode::engine_inexact);
  EXPECT_NEAR(r.warnings[1].value, 0.0, 1e-9);  // frequency met
  // |s| h = omega h = 1.047...: q solves (ln(1 + q^2) / 2)^2 + atan(q)^2 = (omega h)^2.
  double lo = 0.0, hi = 10.0;
  for (int i = 0; i < 200; ++i) {
    const double q = 0.5 * (lo + hi);
    (std::pow(0.5 * std::log1p(q * q), 2) + std::pow(std::atan(q), 2) < std::pow(omega * h, 2) ? lo : hi) = q;
  }
  const double zeta_undamped = 0.5 * std::log1p(lo * lo) / (omega * h);
  EXPECT_NEAR(r.warnings[1].limit, zeta_undamped - zeta, 1e-9);
}

TEST(PhysxModel, TgsSubstepsReachZeroDampingWithinTheTolerance) {
  // 255 position iterations: the undamped drive's own damping is about omega h / 510 = 0.002 < 0.005.
  const double m = 2.0, h = 1.0 / 60.0, hz = 10.0, omega = 2.0 * std::numbers::pi * hz;
  const EngineReport r =
      kPhysxModel.report(target(hz, 0.0, m, h, spring_constants(m, omega, 0.0)), physx_settings(1, 255, 1, 0));
  ASSERT_TRUE(r.exact && r.exact_predicted);
  EXPECT_EQ((*r.exact)[1].value, 0.0);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, 1e-8 * hz);
  EXPECT_LE(*r.exact_predicted->damping_ratio, kExactDampingTolerance);
  EXPECT_GT(*r.exact_predicted->damping_ratio, 0.0);
}

TEST(PhysxModel, DrivesBeyondFloatAreRefused) {
  const double h = 1.0 / 60.0;
  const EngineReport r = kPhysxModel.report(target(1.0, 0.5, 1e30, h, {1e39, 1.0}), default_settings(kPhysxModel));
  EXPECT_TRUE(r.parameters.empty());
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
}

TEST(PhysxModel, NeverExportsOutsideTheLegalRanges) {
  // Whatever is asked, every exported drive passes PxD6JointDrive::isValid in float (stiffness > 0,
  // damping >= 0, both <= FLT_MAX), and an `exact` meets the request as predicted.
  int exported = 0;
  for (const SettingValues& s :
       {physx_settings(0, 4, 1, 0), physx_settings(0, 4, 1, 1), physx_settings(1, 4, 1, 0), physx_settings(1, 255, 0, 1)}) {
    for (double hz : {0.1, 3.0, 40.0, 1000.0}) {
      for (double zeta : {0.0, 1e-3, 0.3, 1.0, 5.0, 50.0}) {
        for (double m : {1e-6, 1.0, 1e6}) {
          for (double h : {1.0 / 30.0, 1.0 / 240.0, 1.0 / 2000.0}) {
            const double omega = 2.0 * std::numbers::pi * hz;
            for (SpringConstants spring : {spring_constants(m, omega, zeta), exact_spring(m, omega, zeta, h).spring}) {
              const EngineReport r = kPhysxModel.report(target(hz, zeta, m, h, spring), s);
              for (const std::optional<Parameters>& p : {std::optional<Parameters>(r.parameters), r.exact}) {
                if (!p || p->empty()) continue;
                ++exported;
                EXPECT_GT((*p)[0].value, 0.0);
                EXPECT_LE((*p)[0].value, kFltMax);
                EXPECT_GE((*p)[1].value, 0.0);
                EXPECT_LE((*p)[1].value, kFltMax);
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

// The conformance grid of the real engines (tests/engines), run on the literal loops above in float, as PhysX
// computes: for each case tune() answers, PhysX's `parameters` and `exact` drive pgs_simulate / tgs_simulate,
// the trajectory is fitted, and the fit is held within 1 % / 0.02 of `predicted`, and for `exact` of the
// request. The rotating plank is not run: the loop sees the row's effective mass only.
struct Worst {
  int runs = 0;
  double frequency = 0.0, damping = 0.0;
  void add(double f, double z) {
    ++runs;
    frequency = std::max(frequency, f);
    damping = std::max(damping, z);
  }
};

std::optional<ResponseFit> run_loop(const Parameters& p, const SettingValues& s, double m, double dt, int steps) {
  const bool acceleration = s[kPhysxDriveType] != 0.0, tgs = s[kPhysxSolverType] != 0.0;
  const float k = static_cast<float>(p[0].value), d = static_cast<float>(p[1].value), h = static_cast<float>(dt);
  const int position = static_cast<int>(s[kPhysxPositionIterations]);
  const int velocity = static_cast<int>(s[kPhysxVelocityIterations]);
  // The loops take the row's mass; an acceleration drive runs on the true mass too (it divides it out).
  const float body_mass = static_cast<float>(m);
  RowT<float> row{1e-2f, 0.0f};
  std::vector<double> x{row.x};
  for (int i = 0; i < steps; ++i) {
    row = tgs ? tgs_simulate<float>(row, body_mass, k, d, h, position, velocity, acceleration)
              : pgs_simulate<float>(row, body_mass, k, d, h, position, velocity, acceleration);
    x.push_back(row.x);
  }
  const ResponseFit fit = fit_response(x, dt);
  if (!fit.frequency_hz || !fit.damping_ratio) return std::nullopt;
  return fit;
}

TEST(PhysxModel, LiteralFloatLoopsMeetTheReportOverTheGrid) {
  std::size_t index = 0;
  while (engine_models()[index] != &kPhysxModel) ++index;
  const SettingValues variants[] = {physx_settings(0, 4, 1, 0), physx_settings(0, 4, 1, 1), physx_settings(1, 4, 1, 0),
                                    physx_settings(1, 4, 1, 1), physx_settings(1, 1, 1, 0), physx_settings(1, 16, 0, 0),
                                    physx_settings(0, 1, 0, 0), physx_settings(1, 255, 1, 1)};
  Worst standard, exact, versus_request;
  int cases = 0, refused = 0, inexact = 0, unfit = 0, at = 0;
  for (double ratio : {0.02, 0.08, 0.17, 0.3}) {
    for (double zeta : {0.0, 0.1, 0.5, 1.0, 2.0}) {
      for (double mass : {1e-3, 1.0, 1e3}) {
        for (int substeps : {1, 3, 8}) {
          for (SoftMode mode : {SoftMode::standard, SoftMode::exact}) {
            const SettingValues& v = variants[at++ % std::size(variants)];
            TuneRequest request;
            request.substeps = substeps;
            request.frequency_hz = ratio * request.fps;
            request.damping_ratio = zeta;
            request.mode = mode;
            request.effective_mass = mass;
            request.engine_settings.resize(index + 1);
            request.engine_settings[index] = v;
            const TuneResult result = tune(request);
            const EngineReport& r = result.engine_reports[index];
            ++cases;
            const double asked_hz = result.omega / (2.0 * std::numbers::pi);
            const int steps = std::clamp(static_cast<int>(8.0 / (asked_hz * result.h)), 300, 4000);
            auto has = [&](WarningCode code) {
              return std::any_of(r.warnings.begin(), r.warnings.end(),
                                 [&](const Warning& w) { return w.code == code; });
            };
            // A run can be fitted when its motion stays above fit_response's floor for a dozen samples and, when
            // over-damped, its fast pole outlives the first step above float's rounding (|z_fast| > 1e-2):
            // a pole that dies within one step leaves a pure exponential whose partner only noise can fit.
            auto fittable = [&](const Parameters& p) {
              const Eigen::Matrix2d a =
                  physx_step_map(v[kPhysxDriveType] != 0.0 ? 1.0 : mass, p[0].value, p[1].value, result.h,
                                 physx_substeps(v));
              const double tr = a.trace(), det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0), disc = tr * tr - 4.0 * det;
              const double radius = disc < 0.0 ? std::sqrt(det) : 0.5 * (std::abs(tr) + std::sqrt(disc));
              const double smallest = disc < 0.0 ? radius : std::abs(det) / radius;
              return std::pow(radius, 12.0) > kFitFloor && smallest > 1e-2;
            };
            if (r.parameters.empty()) {
              EXPECT_TRUE(has(WarningCode::engine_refuses));
              ++refused;
            } else if (r.predicted.frequency_hz && fittable(r.parameters)) {
              const std::optional<ResponseFit> fit = run_loop(r.parameters, v, mass, result.h, steps);
              ASSERT_TRUE(fit) << cases;
              const double fe = std::abs(*fit->frequency_hz / *r.predicted.frequency_hz - 1.0);
              const double ze = std::abs(*fit->damping_ratio - *r.predicted.damping_ratio);
              EXPECT_LE(fe, 0.01) << cases << " " << ratio << " " << zeta << " " << mass << " " << substeps;
              EXPECT_LE(ze, 0.02) << cases << " " << ratio << " " << zeta << " " << mass << " " << substeps;
              standard.add(fe, ze);
            } else {
              ++unfit;
            }
            if (!r.exact) {
              EXPECT_TRUE(has(WarningCode::engine_inexact));
              ++inexact;
              continue;
            }
            if (!fittable(*r.exact)) {
              ++unfit;
              continue;
            }
            const std::optional<ResponseFit> fit = run_loop(*r.exact, v, mass, result.h, steps);
            ASSERT_TRUE(fit) << cases;
            const double fe = std::abs(*fit->frequency_hz / *r.exact_predicted->frequency_hz - 1.0);
            const double ze = std::abs(*fit->damping_ratio - *r.exact_predicted->damping_ratio);
            EXPECT_LE(fe, 0.01) << cases << " exact";
            EXPECT_LE(ze, 0.02) << cases << " exact";
            exact.add(fe, ze);
            const double qe = std::abs(*fit->frequency_hz / asked_hz - 1.0);
            const double qz = std::abs(*fit->damping_ratio - result.damping_ratio);
            EXPECT_LE(qe, 0.01) << cases << " exact vs request";
            EXPECT_LE(qz, 0.02) << cases << " exact vs request";
            versus_request.add(qe, qz);
          }
        }
      }
    }
  }
  std::printf("PhysX 5 literal float loops: %d cases (%d plain exports refused, %d exact null, %d runs decay too fast "
              "to fit in float)\n", cases, refused, inexact, unfit);
  auto row = [](const char* name, const Worst& w) {
    std::printf("  %-26s %4d runs  worst %.3g%% / %.3g\n", name, w.runs, 100 * w.frequency, w.damping);
  };
  row("parameters vs predicted", standard);
  row("exact vs exact_predicted", exact);
  row("exact vs request", versus_request);
  EXPECT_GE(cases, 300);
}

}  // namespace
}  // namespace softtune::engines
