// Bullet 3.24 (Debian's libbullet-dev 3.24, float btScalar as `pkg-config bullet` links it), read in
// src/BulletDynamics:
//   ConstraintSolver/btGeneric6DofSpring2Constraint.cpp
//       get_limit_motor_info2    the spring row (m_enableSpring) and the locked-axis row (m_currentLimit 3)
//       setLinearLimits          per-axis STOP_ERP / STOP_CFM (setParam flags) or the solver's m_erp, m_globalCfm
//       setStiffness/setDamping  limitIfNeeded defaults to true (m_springStiffnessLimited, ..DampingLimited)
//   ConstraintSolver/btSequentialImpulseConstraintSolver.cpp
//       convertJoint             m_jacDiagABInv = 1 / (J M^-1 J^T) (sorRelaxation fixed at 1; m_sor is for
//                                contacts), m_rhs = (m_constraintError - rel_vel m_damping) m_jacDiagABInv,
//                                m_cfm = the row's cfm as typed (no 1/h, no mass), m_appliedImpulse = 0
//       convertJoints            joints are not warm started (SOLVER_USE_WARMSTARTING is read for contacts
//                                only), split impulse is for contacts only
//       gResolveSingleConstraintRowGeneric_scalar_reference (and its SSE2 twin)
//                                deltaImpulse = m_rhs - m_appliedImpulse m_cfm - J dv m_jacDiagABInv, clamped
//                                to [m_lowerLimit, m_upperLimit]
//       solveGroupCacheFriendlyIterations  m_numIterations sweeps (default 10, btContactSolverInfo.h); stops
//                                early only at a residual of exactly 0 (m_leastSquaresResidualThreshold 0)
//   Dynamics/btDiscreteDynamicsWorld.cpp
//       stepSimulation           with maxSubSteps != 0 it steps fixedTimeStep (default 1/60) and interpolates
//                                motion states; stepSimulation(dt, 0) is exactly one internal step of dt
//       internalSingleStepSimulation  applyDamping (0 by default), solve (external forces enter the solver
//                                bodies' velocities), integrateTransforms x1 = x0 + h v1: semi-implicit Euler
//
// The spring2 route. get_limit_motor_info2 computes, with m = 1 / getInvMass() of the dynamic body (the
// reduced mA mB / (mA + mB) for two) and the anchor velocity vel:
//   f = h (k error) - h c vel;  m_constraintError = vel + f / m;  limits [min(f, fd, 0), max(f, fd, 0)]
// so the row asks for the velocity change f / m and the solver's first iteration gives it exactly
// (lambda = m_eff f / m, inside the limits because m_eff <= m); later iterations add nothing. One step is
// semi-implicit Euler on (m, k, c): the spring is explicit, and on an off-centre anchor (m_eff < m) it is
// weaker than typed by m_eff / m. Before that, limitIfNeeded (the default) replaces k by m / (16 h^2) when
// sqrt(k / m) h > 0.25 and c by m / h when c h > m.
//
// The erp_cfm route: a locked axis (lower = upper limit) gives m_constraintError = ERP C / h and cfm = CFM
// as typed. With a = J M^-1 J^T the solver iterates lambda_{j+1} = m_rhs - CFM lambda_j from 0 (one row; the
// body's delta velocity is a lambda_j), so after n iterations the row's velocity change is
// g (ERP C / h - rel_vel), g = sum_{j<n} (-CFM)^j. Converged, g = 1 / (1 + CFM): the row is ODE's soft
// constraint with CFM_ode = CFM h / m_eff, and it diverges for CFM >= 1. Implicit Euler on (m_eff, k, c)
// needs ERP = h k / (h k + c) and CFM = m_eff / (h (h k + c)), above 1 for most soft springs; softtune's old
// export (ODE's CFM = 1 / (h k + c)) is a different spring altogether.
#include "softtune/engines/bullet.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "softtune/designer.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kRouteChoices = {"spring2", "erp_cfm"};
constexpr std::array<SettingSpec, 2> kSettings = {{
    {"route", kBulletRouteSpring2, 0, 1, true, kRouteChoices, "",
     "spring2: enableSpring/setStiffness/setDamping on a free axis; erp_cfm: STOP_ERP/STOP_CFM on a locked "
     "axis"},
    {"m_numIterations", 10, 1, 1000, true, {}, "",
     "btContactSolverInfo::m_numIterations, the solver's sweeps per step (the erp_cfm route depends on it)"},
}};

// btScalar is float in Debian's default build: a value is held as the nearest float.
constexpr double kFloatMax = 3.4028234663852886e38;
double as_float(double value) { return static_cast<double>(static_cast<float>(value)); }
bool float_finite(double value) { return std::isfinite(value) && std::abs(value) <= kFloatMax; }

// x^n for an integer n >= 0, by squaring.
double power(double x, int n) {
  double result = 1.0;
  while (n > 0) {
    if (n & 1) result *= x;
    x *= x;
    n >>= 1;
  }
  return result;
}

// The requested continuous poles z = exp(s h), as the two numbers both routes need: the product
// P = z1 z2 = exp(-2 zeta omega h) (kept as 1 - P) and (1 - z1)(1 - z2), each without cancellation.
struct TargetPoles {
  double one_minus_product = 0.0;  // 1 - P
  double one_minus_z = 0.0;        // (1 - z1)(1 - z2) = 1 - S + P
};
TargetPoles target_poles(double omega, double zeta, double h) {
  TargetPoles out;
  const double a = zeta * omega * h;
  out.one_minus_product = -std::expm1(-2.0 * a);
  if (zeta < 1.0) {
    // z = e exp(+-i theta): (1 - z1)(1 - z2) = (1 - e)^2 + 4 e sin^2(theta / 2).
    const double e = std::exp(-a), one_minus_e = -std::expm1(-a);
    const double half_theta = 0.5 * omega * h * std::sqrt(1.0 - zeta * zeta);
    out.one_minus_z = one_minus_e * one_minus_e + 4.0 * e * std::sin(half_theta) * std::sin(half_theta);
  } else {
    // Real poles s1,2 = -omega (zeta -+ sqrt(zeta^2 - 1)); (1 - z1)(1 - z2) = expm1(s1 h) expm1(s2 h).
    const double root = std::sqrt(zeta * zeta - 1.0);
    out.one_minus_z = std::expm1(-omega * (zeta - root) * h) * std::expm1(-omega * (zeta + root) * h);
  }
  return out;
}

bool meets(const Prediction& p, double omega, double zeta) { return p.stable && meets_response(p, omega, zeta); }

// The m get_limit_motor_info2 computes for a linear spring: the body masses' reduced mass, which the tune
// knows when a constraint was given; otherwise the body is taken to be a point on its anchor (m = m_eff).
double spring_body_mass(const Target& t) {
  return t.box2d_reduced_mass && *t.box2d_reduced_mass > 0.0 ? *t.box2d_reduced_mass : t.effective_mass;
}

// ---- spring2 ----------------------------------------------------------------------------------------

Parameters spring2_parameters(double k, double c, bool limit_k, bool limit_c) {
  return {{kBulletStiffness, k, "N/m"},
          {kBulletDamping, c, "N s/m"},
          {kBulletStiffnessLimit, 0.0, "", limit_k ? kBulletTrue : kBulletFalse},
          {kBulletDampingLimit, 0.0, "", limit_c ? kBulletTrue : kBulletFalse}};
}

// What the engine does with (k, c) as typed (rounded to float); empty when a value is beyond float.
std::optional<Prediction> predict_spring2(double m, double k, double c, double h, bool limit_k, bool limit_c,
                                          BulletSpringInUse* in_use = nullptr) {
  if (!float_finite(k) || !float_finite(c)) return std::nullopt;
  const BulletSpringInUse used = bullet_spring_in_use(m, as_float(k), as_float(c), h, limit_k, limit_c);
  if (in_use) *in_use = used;
  return predict_from_step_map(bullet_spring2_step_map(m, used.stiffness, used.damping, h), h);
}

void report_spring2(const Target& t, EngineReport& out) {
  const double m = spring_body_mass(t), h = t.dt;
  const double k = t.spring.stiffness, c = t.spring.damping;
  // The plain export: setStiffness(axis, k) and setDamping(axis, c) with Bullet's default limitIfNeeded.
  out.parameters = spring2_parameters(float_finite(k) ? as_float(k) : k, float_finite(c) ? as_float(c) : c,
                                      true, true);
  BulletSpringInUse used;
  if (const std::optional<Prediction> p = predict_spring2(m, k, c, h, true, true, &used)) {
    out.predicted = *p;
    if (used.stiffness_limited) {
      out.warnings.push_back({WarningCode::engine_refuses, k, used.stiffness, kBulletModel.name,
                              "setStiffness(axis, k) with limitIfNeeded (the default) replaces k by "
                              "m / (16 h^2) where sqrt(k / m) h > 0.25"});
    }
    if (used.damping_limited) {
      out.warnings.push_back({WarningCode::engine_refuses, c, used.damping, kBulletModel.name,
                              "setDamping(axis, c) with limitIfNeeded (the default) replaces c by m / h "
                              "where c h > m"});
    }
    if (!p->stable) {
      out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kBulletModel.name,
                              "the spring is explicit (semi-implicit Euler): a negative damping or "
                              "sqrt(k / m) h above 2 grows"});
    }
  } else {
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, k, kFloatMax, kBulletModel.name,
                            "stiffness and damping are float (btScalar): beyond 3.4e38 they are infinite"});
  }

  // Exact: semi-implicit Euler on (m, k, c) has det = 1 - h c / m and trace = 2 - h (h k + c) / m, so the
  // poles exp(s h) need c = m (1 - P) / h and k = m (1 - z1)(1 - z2) / h^2: a closed form for every
  // request, with limitIfNeeded off where Bullet's limit would replace that k.
  if (!(t.omega > 0.0)) return;
  const TargetPoles poles = target_poles(t.omega, t.damping_ratio, h);
  const double k_exact = m * poles.one_minus_z / (h * h), c_exact = m * poles.one_minus_product / h;
  const bool limit_k = !bullet_spring_in_use(m, k_exact, 0.0, h, true, false).stiffness_limited;
  const bool limit_c = !bullet_spring_in_use(m, 0.0, c_exact, h, false, true).damping_limited;
  const std::optional<Prediction> p = predict_spring2(m, k_exact, c_exact, h, limit_k, limit_c);
  if (p && meets(*p, t.omega, t.damping_ratio)) {
    out.exact = spring2_parameters(as_float(k_exact), as_float(c_exact), limit_k, limit_c);
    out.exact_predicted = *p;
  } else {
    const double f_error = p && p->frequency_hz ? *p->frequency_hz / frequency_from_angular(t.omega) - 1.0
                                                : std::numeric_limits<double>::infinity();
    const double z_error = p && p->damping_ratio ? *p->damping_ratio - t.damping_ratio
                                                 : std::numeric_limits<double>::infinity();
    out.warnings.push_back({WarningCode::engine_inexact, f_error, z_error, kBulletModel.name,
                            "the poles asked are beyond one step's reach (above Nyquist, or a float "
                            "stiffness or damping cannot hold them)"});
  }
}

// ---- erp_cfm ----------------------------------------------------------------------------------------

Parameters erp_cfm_parameters(double erp, double cfm) {
  return {{kBulletStopErp, erp, ""}, {kBulletStopCfm, cfm, ""}};
}

// The legal range softtune exports in: 0 < ERP <= 1 (Bullet's documented range; above 1 the bias
// overshoots the error) and 0 <= CFM < 1 (at and above 1 the iteration diverges as it is repeated).
bool erp_cfm_legal(double erp, double cfm) { return erp > 0.0 && erp <= 1.0 && cfm >= 0.0 && cfm < 1.0; }

Prediction predict_erp_cfm(double erp, double cfm, int n, double h) {
  return predict_from_step_map(bullet_erp_cfm_step_map(as_float(erp), as_float(cfm), n, h), h);
}

void report_erp_cfm(const Target& t, int n, EngineReport& out) {
  const double h = t.dt, k = t.spring.stiffness, c = t.spring.damping;
  // The plain export: what softtune exported for ODE and Bullet alike, ERP = h k / (h k + c),
  // CFM = 1 / (h k + c) (ODE's force-form CFM, engine_export.cpp).
  const double denominator = h * k + c;
  if (!(denominator > 0.0) || !float_finite(1.0 / denominator)) {
    out.parameters = erp_cfm_parameters(0.0, 0.0);
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, denominator, 0.0, kBulletModel.name,
                            "ERP = h k / (h k + c) and CFM = 1 / (h k + c) need h k + c > 0"});
  } else {
    const double erp = as_float(h * k / denominator), cfm = as_float(1.0 / denominator);
    out.parameters = erp_cfm_parameters(erp, cfm);
    out.predicted = predict_erp_cfm(erp, cfm, n, h);
    if (!(erp > 0.0 && erp <= 1.0)) {
      out.warnings.push_back({WarningCode::engine_refuses, erp, 1.0, kBulletModel.name,
                              "ERP is an error reduction in 0..1 (btConstraintInfo2); above 1 the bias "
                              "overshoots the error"});
    }
    if (!(cfm < 1.0)) {
      out.warnings.push_back({WarningCode::engine_refuses, cfm, 1.0, kBulletModel.name,
                              "a CFM of 1 or more makes the solver's sweeps lambda = rhs - CFM lambda "
                              "diverge as they repeat"});
    }
    if (!out.predicted.stable) {
      out.warnings.push_back({WarningCode::engine_unstable, out.predicted.spectral_radius, 1.0,
                              kBulletModel.name,
                              "Bullet's CFM is not ODE's: the solver repeats lambda = rhs - CFM lambda, "
                              "which diverges for CFM >= 1"});
    }
  }

  // Exact: the step has det = 1 - g and trace = 2 - g - g ERP, so the poles exp(s h) need g = 1 - P and
  // ERP = (1 - z1)(1 - z2) / (1 - P), then the CFM whose n-iteration gain is g.
  if (!(t.omega > 0.0)) return;
  const TargetPoles poles = target_poles(t.omega, t.damping_ratio, h);
  const double gain = poles.one_minus_product;
  const double erp = poles.one_minus_z / gain;
  const std::optional<double> cfm = erp <= 1.0 ? bullet_cfm_for_gain(gain, n) : std::nullopt;
  if (cfm && erp_cfm_legal(as_float(erp), as_float(*cfm))) {
    const Prediction p = predict_erp_cfm(erp, *cfm, n, h);
    if (meets(p, t.omega, t.damping_ratio)) {
      out.exact = erp_cfm_parameters(as_float(erp), as_float(*cfm));
      out.exact_predicted = p;
      return;
    }
  }
  // The nearest legal (ERP, CFM): the response solver, held inside the legal range.
  const double erp_guess = std::isfinite(erp) && erp > 0.0 ? std::min(erp, 1.0) : 1.0;
  const std::optional<double> cfm_guess = bullet_cfm_for_gain(std::max(gain, 1e-3), n);
  const ResponseSolve solve = solve_response(
      [&](double erp_try, double cfm_try) -> std::optional<Prediction> {
        if (!erp_cfm_legal(as_float(erp_try), as_float(cfm_try))) return std::nullopt;
        return predict_erp_cfm(erp_try, cfm_try, n, h);
      },
      t.omega, t.damping_ratio, erp_guess, cfm_guess.value_or(0.0));
  if (solve.met) {
    out.exact = erp_cfm_parameters(as_float(solve.p0), as_float(solve.p1));
    out.exact_predicted = solve.prediction;
    return;
  }
  std::string_view why =
      erp > 1.0 ? "the request needs ERP above 1 (its exact damping is negative): ERP/CFM on a locked axis "
                  "always damps; the spring2 route meets it"
      : !cfm    ? "no CFM in [0, 1) gives the gain the request needs at this iteration count (zero damping "
                  "needs CFM = 1, an odd count has a least gain); the spring2 route meets it"
                : "the CFM the request needs is too close to 1 for a float to hold";
  out.warnings.push_back({WarningCode::engine_inexact, solve.frequency_error, solve.damping_error,
                          kBulletModel.name, why});
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kBulletModel, values);
  const double route = values.size() > kBulletRouteSetting ? values[kBulletRouteSetting] : kBulletRouteSpring2;
  const int n = values.size() > kBulletIterationsSetting
                    ? std::max(1, static_cast<int>(values[kBulletIterationsSetting]))
                    : 10;
  if (route == kBulletRouteErpCfm) {
    report_erp_cfm(t, n, out);
  } else {
    report_spring2(t, out);
  }
  return out;
}

}  // namespace

// get_limit_motor_info2: angularfreq = sqrt(ks / m); if (m_springStiffnessLimited && 0.25 < angularfreq dt)
// ks = 1 / dt / dt / 16 * m; if (m_springDampingLimited && kd * dt > m) kd = m / dt.
BulletSpringInUse bullet_spring_in_use(double body_mass, double stiffness, double damping, double h,
                                       bool limit_stiffness, bool limit_damping) {
  BulletSpringInUse out{stiffness, damping, false, false};
  if (limit_stiffness && kBulletSpringOmegaHLimit < std::sqrt(stiffness / body_mass) * h) {
    out.stiffness = body_mass / (16.0 * h * h);
    out.stiffness_limited = true;
  }
  if (limit_damping && damping * h > body_mass) {
    out.damping = body_mass / h;
    out.damping_limited = true;
  }
  return out;
}

// get_limit_motor_info2: fs = ks error dt, fd = -kd vel dt, m_constraintError = vel + (fs + fd) / m; the
// solver reaches it (resolveSingleConstraintRowGeneric), then integrateTransforms moves x by h v1.
Eigen::Matrix2d bullet_spring2_step_map(double body_mass, double stiffness, double damping, double h) {
  Eigen::Matrix2d a;
  a(1, 0) = -h * stiffness / body_mass;      // v1 = v0 - (h / m)(k x0 + c v0)
  a(1, 1) = 1.0 - h * damping / body_mass;
  a(0, 0) = 1.0 + h * a(1, 0);               // x1 = x0 + h v1
  a(0, 1) = h * a(1, 1);
  return a;
}

// resolveSingleConstraintRowGeneric from m_appliedImpulse = 0: deltaImpulse = m_rhs - lambda_j CFM - lambda_j
// (the body's delta velocity along the row is lambda_j / m_jacDiagABInv), so lambda_{j+1} = m_rhs - CFM lambda_j.
double bullet_cfm_gain(double cfm, int iterations) {
  if (cfm == -1.0) return static_cast<double>(iterations);
  const double odd = (iterations & 1) ? -1.0 : 1.0;  // (-c)^n = odd c^n
  return (1.0 - odd * power(cfm, iterations)) / (1.0 + cfm);
}

// convertJoint: m_rhs = (fps ERP C - rel_vel) m_jacDiagABInv; the row's velocity change is g m_rhs / m_jacDiagABInv.
Eigen::Matrix2d bullet_erp_cfm_step_map(double erp, double cfm, int iterations, double h) {
  const double g = bullet_cfm_gain(cfm, iterations);
  Eigen::Matrix2d a;
  a(1, 0) = -g * erp / h;  // v1 = (1 - g) v0 - g (ERP / h) x0
  a(1, 1) = 1.0 - g;
  a(0, 0) = 1.0 + h * a(1, 0);  // x1 = x0 + h v1
  a(0, 1) = h * a(1, 1);
  return a;
}

std::optional<double> bullet_cfm_for_gain(double gain, int n) {
  if (!(gain > 0.0) || !(gain <= 1.0) || n < 1) return std::nullopt;
  if (gain == 1.0) return 0.0;
  if (n == 1) return std::nullopt;  // one sweep ignores the CFM: the gain is 1
  // F(c) = 1 - (-c)^n - g (1 + c) = 0 is g_n(c) = g. Even n: F is concave and falls from 1 - g at 0 to -2 g
  // at 1, so Newton from c = 1 converges from the right without overshooting. Odd n: F is convex, falls from
  // 1 - g at 0 to its least value at c = (g / n)^(1 / (n - 1)); Newton from 0 converges from the left.
  const bool even = (n & 1) == 0;
  if (!even) {
    const double c_low = std::pow(gain / n, 1.0 / (n - 1));
    if (1.0 + power(c_low, n) - gain * (1.0 + c_low) > 0.0) return std::nullopt;
  }
  double c = even ? 1.0 : 0.0;
  for (int i = 0; i < 100; ++i) {
    const double cn1 = power(c, n - 1);
    const double f = even ? 1.0 - cn1 * c - gain * (1.0 + c) : 1.0 + cn1 * c - gain * (1.0 + c);
    const double df = even ? -n * cn1 - gain : n * cn1 - gain;
    const double step = f / df;
    c -= step;
    if (!(std::abs(step) > 1e-15)) break;
  }
  if (!(c >= 0.0 && c < 1.0)) return std::nullopt;
  return c;
}

const EngineModel kBulletModel = {
    "bullet",
    "Bullet 3.24 (float): btGeneric6DofSpring2Constraint.cpp get_limit_motor_info2, setLinearLimits; "
    "btSequentialImpulseConstraintSolver.cpp convertJoint, resolveSingleConstraintRowGeneric; "
    "btDiscreteDynamicsWorld.cpp stepSimulation, internalSingleStepSimulation",
    kSettings,
    report,
};

}  // namespace softtune::engines
