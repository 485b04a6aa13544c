// MuJoCo 2.2.2 (Debian's libmujoco-dev), read at tag 2.2.2 of google-deepmind/mujoco and compared with 3.x
// (HEAD, same lines unless said):
//   src/engine/engine_core_constraint.c
//     getsolparam        mixed solref -> mj_defaultSolRefImp (0.02, 1); solref[0] = max(solref[0], 2 timestep)
//                        unless mjDSBL_REFSAFE; solimp[0], [1], [3] clamped to [mjMINIMP, mjMAXIMP]
//     getimpedance       flat (imp = (solimp[0] + solimp[1]) / 2) when solimp[0] == solimp[1]
//     mj_makeImpedance   R = max(mjMINVAL, (1 - imp) diagApprox / imp);
//                        standard K = 1 / (dmax^2 timeconst^2 dampratio^2), B = 2 / (dmax timeconst);
//                        direct   K = -solref[0] / dmax^2, B = -solref[1] / dmax   (dmax = solimp[1])
//     mj_referenceConstraint  aref = -B vel - K imp (pos - margin)
//     mj_diagApprox      joint / tendon equality: dof_invweight0 / tendon_invweight0, which
//                        engine_setconst.c computes as the exact J M^-1 J' at qpos0 (connect and weld use
//                        body_invweight0, a body's inverse mass averaged over three axes: not an anchor's)
//     mj_constraintUpdate  equality rows: force = -D (J qacc - aref), D = 1 / R (quadratic cost)
//   src/engine/engine_forward.c
//     mj_Euler / mj_EulerSkip  qacc from the solver, implicit only in dof_damping; mj_advance:
//                        qvel += h qacc, then qpos integrated with the new qvel (semi-implicit)
//     mj_implicit        (M - h qDeriv) qacc = qfrc_smooth + qfrc_constraint, qDeriv = d qfrc_smooth / d qvel:
//                        the constraint force is not differentiated; implicitfast (3.x) likewise
//     mj_RungeKutta      classic RK4, mj_forward at each stage (constraints rebuilt at each stage)
//
// The solver minimises 1/2 (qacc - qacc0)' M (qacc - qacc0) + 1/2 D (J qacc - aref)^2; for one row with
// A = J M^-1 J' its constraint acceleration is
//   J qacc = (J qacc0 + A D aref) / (1 + A D) = g aref + (1 - g) J qacc0,  A D = rho imp / (1 - imp),
//   g = rho imp / (1 - imp + rho imp),  rho = A / diagApprox,
// and for a joint or tendon equality rho = 1, g = imp (the docs' "a1 + d (b v + k r) = (1 - d) a0").
// With no other force: a = -g B v - g imp K r: a spring per unit effective mass, independent of the mass.
// (A connect or weld row has rho != 1 on an off-centre anchor: the diag_ratio setting carries it.) With
// rho = 1 and a flat solimp at imp = dmax, standard solref (timeconst, dampratio) is exactly
// omega = 1 / (timeconst dampratio), zeta = dampratio, and direct (-k, -b) is exactly a = -b v - k r. The integrators then step it explicitly (the constraint force uses
// r and v at the start of the step): Euler, implicit and implicitfast are the same semi-implicit Euler
// map, RK4 is RK4; none is the implicit Euler softtune's own exact springs assume.
#include "softtune/engines/mujoco.h"

#include <array>
#include <cmath>
#include <complex>
#include <limits>

#include "softtune/designer.h"

namespace softtune::engines {
namespace {

constexpr double kMax = std::numeric_limits<double>::max();
constexpr std::array<std::string_view, 4> kIntegratorChoices = {"Euler", "RK4", "implicit", "implicitfast"};
constexpr std::array<std::string_view, 2> kRefsafeChoices = {"enable", "disable"};
constexpr std::array<SettingSpec, kMujocoSettingCount> kSettings = {{
    {"integrator", 0, 0, 3, true, kIntegratorChoices, "",
     "mjOption integrator; Euler, implicit and implicitfast step one constraint alike"},
    {"solimp[0]", 0.9, kMujocoMinImp, kMujocoMaxImp, false, {}, "",
     "d0: impedance at zero violation; the export sets it to solimp[1] (a flat, linear impedance)"},
    {"solimp[1]", 0.95, kMujocoMinImp, kMujocoMaxImp, false, {}, "",
     "d_width: impedance at and beyond width; solref's K and B are divided by it"},
    {"solimp[2]", 0.001, 0, kMax, false, {}, "m", "width of the impedance transition"},
    {"solimp[3]", 0.5, kMujocoMinImp, kMujocoMaxImp, false, {}, "", "midpoint of the transition"},
    {"solimp[4]", 2, 1, kMax, false, {}, "", "power of the transition"},
    {"refsafe", 0, 0, 1, true, kRefsafeChoices, "",
     "mjDSBL_REFSAFE off (enable): standard timeconst raised to 2 timestep"},
    {"diag_ratio", 1, 1e-6, 1e6, false, {}, "",
     "J M^-1 J' / efc_diagApprox: 1 for a joint or tendon equality; connect/weld: 1/m_eff / body_invweight0"},
}};

struct Config {
  MujocoIntegrator integrator = MujocoIntegrator::euler;
  std::array<double, 5> solimp{};  // as exported: solimp[0] = solimp[1]
  bool refsafe = true;
  double rho = 1.0;  // J M^-1 J' / efc_diagApprox
  // g / d: the fraction of aref the solver realises over the impedance (1 when rho = 1)
  double realised() const {
    const double d = solimp[1];
    return rho / (1.0 - d + rho * d);
  }
};

Config config_of(const SettingValues& v) {
  Config c;
  c.integrator = static_cast<MujocoIntegrator>(static_cast<int>(v[kMujocoIntegrator]));
  c.solimp = {v[kMujocoSolimp1], v[kMujocoSolimp1], v[kMujocoSolimp2], v[kMujocoSolimp3], v[kMujocoSolimp4]};
  c.refsafe = v[kMujocoRefsafe] == 0.0;
  c.rho = v[kMujocoDiagRatio];
  return c;
}

Parameters parameters_of(double solref0, double solref1, const Config& c) {
  return {{"solref[0]", solref0, solref0 > 0.0 ? "s" : "1/s^2"},
          {"solref[1]", solref1, solref0 > 0.0 ? "" : "1/s"},
          {"solimp[0]", c.solimp[0]},
          {"solimp[1]", c.solimp[1]},
          {"solimp[2]", c.solimp[2], "m"},
          {"solimp[3]", c.solimp[3]},
          {"solimp[4]", c.solimp[4]}};
}

Prediction predict_gains(const MujocoGains& g, const Config& c, double h) {
  return predict_from_step_map(mujoco_step_map(c.integrator, g.beta, g.kappa, h), h);
}

// The (solref[0], solref[1]) that make MuJoCo's gains (beta, kappa) at the flat impedance d = solimp[1]:
// standard when there is damping and the 2h floor leaves the timeconst alone, else direct.
// With imp = dmax the standard form gives beta = q 2 / timeconst, kappa = q / (timeconst dampratio)^2 and the
// direct form beta = -q solref[1], kappa = -q solref[0], whatever d is (q = g / d, 1 when rho = 1).
std::array<double, 2> solref_of(double beta, double kappa, const Config& c, double h) {
  const double q = c.realised();
  if (beta > 0.0) {
    const double timeconst = 2.0 * q / beta;
    if (!c.refsafe || timeconst >= 2.0 * h) return {timeconst, std::sqrt(q / kappa) / timeconst};
  }
  return {-kappa / q, beta > 0.0 ? -beta / q : 0.0};
}

// The poles of a continuous oscillator (omega, zeta) over h, as z = exp(s h): s1 and s2 (complex pair
// with Im s1 >= 0, or two reals).
std::array<std::complex<double>, 2> continuous_poles(double omega, double zeta) {
  if (zeta < 1.0) {
    const std::complex<double> s(-zeta * omega, omega * std::sqrt(1.0 - zeta * zeta));
    return {s, std::conj(s)};
  }
  const double root = std::sqrt(zeta * zeta - 1.0);
  // s1 = -omega (zeta - root) written without cancellation.
  return {std::complex<double>(-omega / (zeta + root), 0.0), std::complex<double>(-omega * (zeta + root), 0.0)};
}

// Semi-implicit Euler's gains for the poles exp(s h): the map's characteristic polynomial is
// z^2 - (2 - h beta - h^2 kappa) z + (1 - h beta), so h beta = 1 - P, h^2 kappa = (1 - z1)(1 - z2).
MujocoGains euler_exact_gains(double omega, double zeta, double h) {
  MujocoGains g;
  g.beta = -std::expm1(-2.0 * zeta * omega * h) / h;
  if (zeta < 1.0) {
    const double a = -std::expm1(-zeta * omega * h), e = std::exp(-zeta * omega * h);
    const double half = std::sin(0.5 * omega * std::sqrt(1.0 - zeta * zeta) * h);
    g.kappa = (a * a + 4.0 * e * half * half) / (h * h);
  } else {
    const auto s = continuous_poles(omega, zeta);
    g.kappa = std::expm1(s[0].real() * h) * std::expm1(s[1].real() * h) / (h * h);
  }
  return g;
}

// RK4's step map is T4(A h), T4(w) = 1 + w + w^2/2 + w^3/6 + w^4/24, whose eigenvalues are T4(lambda h):
// matching exp(s h) needs T4(w) = exp(s h), solved by Newton from w = s h (T4' = T3).
std::complex<double> rk4_root(std::complex<double> sh) {
  const std::complex<double> z = std::exp(sh);
  std::complex<double> w = sh;
  for (int i = 0; i < 30; ++i) {
    const std::complex<double> t3 = 1.0 + w * (1.0 + w * (0.5 + w * (1.0 / 6.0)));
    const std::complex<double> t4 = 1.0 + w * (1.0 + w * (0.5 + w * (1.0 / 6.0 + w * (1.0 / 24.0))));
    // (t4 - z) / t3 without the library's scaled complex division
    const std::complex<double> step = (t4 - z) * std::conj(t3) / std::norm(t3);
    w -= step;
    // Newton converges quadratically: once a step is 1e-13 of w, the next would be below rounding.
    if (std::norm(step) <= 1e-26 * std::max(1.0, std::norm(w))) return w;
  }
  // No root near s h: a real pole below T4's real minimum (0.27 at w = -1.6) has none.
  return {std::numeric_limits<double>::quiet_NaN(), 0.0};
}

MujocoGains rk4_exact_gains(double omega, double zeta, double h) {
  const auto s = continuous_poles(omega, zeta);
  MujocoGains g;
  if (zeta < 1.0) {
    const std::complex<double> lambda = rk4_root(s[0] * h) / h;
    g.kappa = std::norm(lambda);
    g.beta = -2.0 * lambda.real();
  } else {
    const double l1 = rk4_root(s[0] * h).real() / h, l2 = rk4_root(s[1] * h).real() / h;
    g.kappa = l1 * l2;
    g.beta = -(l1 + l2);
  }
  return g;
}

bool meets(const Prediction& p, double omega, double zeta) { return p.stable && meets_response(p, omega, zeta); }

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kMujocoModel, values);
  const Config c = config_of(values);
  const double m = t.effective_mass, h = t.dt, d = c.solimp[1];

  // The plain export (engine_export.cpp): standard (1 / (zeta omega), zeta) of the spring in use when it
  // has damping and 1 / (zeta omega) >= 2h, else direct (-k / m, -c / m).
  const double k = t.spring.stiffness, cd = t.spring.damping;
  double solref0 = -k / m, solref1 = -cd / m;
  if (k > 0.0) {
    const double omega = std::sqrt(k / m), zeta = cd / (2.0 * m * omega);
    if (zeta > 0.0 && 1.0 / (zeta * omega) >= 2.0 * h) {
      solref0 = 1.0 / (zeta * omega);
      solref1 = zeta;
    }
  }
  if (solref0 == 0.0) solref0 = 0.0;  // no "-0" in what to type
  if (solref1 == 0.0) solref1 = 0.0;
  out.parameters = parameters_of(solref0, solref1, c);
  const MujocoGains plain = mujoco_gains(solref0, solref1, d, d, h, c.refsafe, c.rho);
  out.predicted = predict_gains(plain, c, h);
  if (plain.replaced_by_default) {
    out.warnings.push_back({WarningCode::engine_refuses, solref1, kMujocoDefaultTimeconst, kMujocoModel.name,
                            "solref mixes signs (timeconst > 0 with damping <= 0, or stiffness <= 0 with "
                            "damping > 0): MuJoCo warns 'mixed solref format' and uses its default (0.02, 1)"});
  } else if (plain.floored) {
    out.warnings.push_back({WarningCode::engine_refuses, solref0, 2.0 * h, kMujocoModel.name,
                            "timeconst below 2 timestep: MuJoCo raises it to 2 timestep (refsafe)"});
  }
  if (!out.predicted.stable) {
    out.warnings.push_back({WarningCode::engine_unstable, out.predicted.spectral_radius, 1.0, kMujocoModel.name,
                            "MuJoCo steps the constraint force explicitly: h B > 2 or a stiffness beyond "
                            "the integrator's stability limit diverges (qacc NaN, mj_checkAcc resets)"});
  }

  // Exact: the gains whose step map has the poles exp(s h), in closed form; the solver finds the nearest
  // where the closed form asks for what solref cannot hold (RK4 below its own numerical damping).
  if (t.omega > 0.0) {
    const bool rk4 = c.integrator == MujocoIntegrator::rk4;
    const MujocoGains want = rk4 ? rk4_exact_gains(t.omega, t.damping_ratio, h)
                                 : euler_exact_gains(t.omega, t.damping_ratio, h);
    auto predict_solref = [&](double s0, double s1) -> std::optional<Prediction> {
      if (!std::isfinite(s0) || !std::isfinite(s1)) return std::nullopt;
      const MujocoGains g = mujoco_gains(s0, s1, d, d, h, c.refsafe, c.rho);
      if (g.replaced_by_default || g.floored) return std::nullopt;
      return predict_gains(g, c, h);
    };
    std::optional<Prediction> p;
    std::array<double, 2> solref{};
    if (std::isfinite(want.beta) && std::isfinite(want.kappa) && want.kappa > 0.0 && want.beta >= 0.0) {
      solref = solref_of(want.beta, want.kappa, c, h);
      p = predict_solref(solref[0], solref[1]);
    }
    if (p && meets(*p, t.omega, t.damping_ratio)) {
      out.exact = parameters_of(solref[0], solref[1], c);
      out.exact_predicted = *p;
    } else {
      // Search the gains (kappa, beta >= 0): beta < 0 would be a mixed solref; any other pair has a solref.
      const bool usable = want.kappa > 0.0 && std::isfinite(want.kappa) && std::isfinite(want.beta);
      const double guess_kappa = usable ? want.kappa : t.omega * t.omega;
      const double guess_beta = usable ? std::max(0.0, want.beta) : 2.0 * t.damping_ratio * t.omega;
      const ResponseSolve solve = solve_response(
          [&](double kappa, double beta) -> std::optional<Prediction> {
            if (beta < 0.0) return std::nullopt;
            return predict_from_step_map(mujoco_step_map(c.integrator, beta, kappa, h), h);
          },
          t.omega, t.damping_ratio, guess_kappa, guess_beta);
      if (solve.met) {
        const std::array<double, 2> s = solref_of(solve.p1, solve.p0, c, h);
        const std::optional<Prediction> ps = predict_solref(s[0], s[1]);
        out.exact = parameters_of(s[0], s[1], c);
        out.exact_predicted = ps ? *ps : solve.prediction;
      } else {
        out.warnings.push_back(
            {WarningCode::engine_inexact, solve.frequency_error, solve.damping_error, kMujocoModel.name,
             rk4 ? "RK4 cannot reach it: below its own numerical damping it needs a negative solref damping (a "
                   "mixed solref, replaced by the default), a decay faster than 0.27 per step has no RK4 "
                   "root, or the request is above the step's Nyquist rate"
                 : "the request is above the step's Nyquist rate: no solref reaches it"});
      }
    }
  }
  return out;
}

}  // namespace

MujocoGains mujoco_gains(double solref0, double solref1, double imp, double d_width, double h, bool refsafe,
                         double rho) {
  MujocoGains g;
  // getsolparam: "check reference format: standard or direct, cannot be mixed"
  if ((solref0 > 0.0) != (solref1 > 0.0)) {
    solref0 = kMujocoDefaultTimeconst;
    solref1 = kMujocoDefaultDampratio;
    g.replaced_by_default = true;
  }
  // getsolparam: "integrator safety: impose ref[0]>=2*timestep for standard format"
  if (refsafe && solref0 > 0.0 && solref0 < 2.0 * h) {
    solref0 = 2.0 * h;
    g.floored = true;
  }
  // mj_makeImpedance: K, B (dmax = solimp[1])
  const double dmax = d_width;
  const double stiffness = solref0 > 0.0
                               ? 1.0 / std::max(kMujocoMinVal, dmax * dmax * solref0 * solref0 * solref1 * solref1)
                               : -solref0 / std::max(kMujocoMinVal, dmax * dmax);
  const double damping = solref1 > 0.0 ? 2.0 / std::max(kMujocoMinVal, dmax * solref0)
                                       : -solref1 / std::max(kMujocoMinVal, dmax);
  // mj_referenceConstraint: aref = -B v - K imp r; the solver realises g aref (see the top comment), g = imp
  // when efc_diagApprox is the row's J M^-1 J'.
  const double realised = rho * imp / (1.0 - imp + rho * imp);
  g.beta = realised * damping;
  g.kappa = realised * imp * stiffness;
  g.timeconst_used = solref0 > 0.0 ? solref0 : 0.0;
  return g;
}

Eigen::Matrix2d mujoco_step_map(MujocoIntegrator integrator, double beta, double kappa, double h) {
  Eigen::Matrix2d a;
  if (integrator == MujocoIntegrator::rk4) {
    // mj_RungeKutta with RK4_A, RK4_B: for x' = A x the classic scheme is exactly T4(A h).
    Eigen::Matrix2d ah;
    ah << 0.0, h, -kappa * h, -beta * h;
    const Eigen::Matrix2d i = Eigen::Matrix2d::Identity();
    a = i + ah * (i + ah * (0.5 * i + ah * (i / 6.0 + ah / 24.0)));
    return a;
  }
  // mj_Euler (no dof_damping) / mj_implicit / implicitfast (qDeriv = 0 without passive or actuator
  // velocity terms): qacc = a(r0, v0); mj_advance: v1 = v0 + h qacc, r1 = r0 + h v1.
  a(1, 0) = -h * kappa;
  a(1, 1) = 1.0 - h * beta;
  a(0, 0) = 1.0 + h * a(1, 0);
  a(0, 1) = h * a(1, 1);
  return a;
}

const EngineModel kMujocoModel = {
    "mujoco",
    "MuJoCo 2.2.2 (and 3.x): engine_core_constraint.c getsolparam, getimpedance, mj_makeImpedance, "
    "mj_referenceConstraint, mj_diagApprox; engine_forward.c mj_Euler, mj_implicit, mj_RungeKutta",
    kSettings,
    report,
};

}  // namespace softtune::engines
