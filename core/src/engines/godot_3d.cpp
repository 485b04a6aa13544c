// Godot 3.2.3 (Debian's godot3-server 3.2.3-stable, real_t float), 3-D, read in godotengine/godot (3.2
// branch) and the Bullet 2.89 it bundles (thirdparty/bullet):
//   modules/bullet/generic_6dof_joint_bullet.cpp  Generic6DOFJointBullet: a btGeneric6DofSpring2Constraint;
//       set_param(G6DOF_JOINT_LINEAR_SPRING_STIFFNESS / _DAMPING) writes m_springStiffness / m_springDamping
//       straight into the translational motor (so m_springStiffnessLimited / ..DampingLimited stay false: no
//       limitIfNeeded), set_flag(ENABLE_LINEAR_LIMIT, false) is setLimit(axis, 0, -1) (free)
//   modules/bullet/space_bullet.cpp  SpaceBullet::step: dynamicsWorld->stepSimulation(delta, 0, 0), one
//       internal step of the physics step
//   modules/bullet/rigid_body_bullet.cpp  the body's damping is the space's default_linear_damp plus the
//       body's linear_damp (when >= 0): measured in Godot, v *= 1 - h (0.1 + linear_damp) per step
//   BulletDynamics/Dynamics/btDiscreteDynamicsWorld.cpp  predictUnconstraintMotion: applyDamping before the
//       constraints; integrateTransforms after: x1 = x + h v1
//   BulletDynamics/ConstraintSolver/btGeneric6DofSpring2Constraint.cpp  get_limit_motor_info2, the spring:
//       fs = h k error, fd = -h c vel, f = fs + fd; m_constraintError = +-infinity with f's sign, limits
//       [min(f, fd, 0), max(f, fd, 0)]: the solver drives the row to the limit on f's side, so the impulse is
//       f -- unless fd has f's sign and is larger, then fd. vel is the bodies' linear (centre) velocity.
//   servers/physics/joints/generic_6dof_joint_sw.cpp  GodotPhysics 3-D: G6DOFTranslationalLimitMotorSW has no
//       spring; the joint's set_param and set_flag ignore the spring parameters and flags (measured: a body
//       on the spring alone never moves)
//
// On mass m, x the stretch, v its rate, one step of h (Bullet):
//   v' = D v,  D = 1 - h (default_linear_damp + max(linear_damp, 0))     applyDamping
//   F = -h (k x + c v'),  Fd = -h c v'                                    the row, in the body's terms
//   P = Fd when F Fd > 0 and |Fd| > |F| (towards the rest point, the damper stronger), else F
//   v1 = v' + P / m,  x1 = x + h v1
// With P = F always this is semi-implicit Euler after the damping; the other branch drops the spring for
// that step, so a damped spring is damped more than typed (issue 33: k 1, c 1 -> zeta 0.79 for 0.5). The map
// is piecewise linear and positively homogeneous: the motion from any amplitude is the same shape, so the
// model steps it from x = 1 and reads frequency and damping with softtune's response fit
// (core/response_fit.h), as the conformance test reads Godot's own trajectory.
#include "softtune/engines/godot_3d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <utility>
#include <numbers>

#include "report_lines.h"
#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"
#include "softtune/response_fit.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kEngines = {"Bullet", "GodotPhysics"};
constexpr std::array<SettingSpec, 3> kSettings = {{
    {"physics/3d/physics_engine", 0, 0, 1, true, kEngines, "",
     "the 3-D backend: Bullet (Godot 3.2's DEFAULT) or GodotPhysics, whose joints have no springs"},
    {"physics/3d/default_linear_damp", 0.1, 0, 1e6, false, {}, "1/s", "the project's damping, added to the body's"},
    {"linear_damp", -1, -1, 1e6, false, {}, "1/s", "RigidBody.linear_damp: added to the project's when >= 0"},
}};

constexpr double kFloatMax = 3.4028234663852886e38;

Parameters parameters_of(double k, double c) {
  return {{"Generic6DOFJoint.linear_spring_x/stiffness", k, "N/m"},
          {"Generic6DOFJoint.linear_spring_x/damping", c, "N s/m"}};
}

// The linear part (P = F on every step): semi-implicit Euler after the damping, det = D (1 - h c / m),
// trace = det + 1 - h^2 k / m.
Eigen::Matrix2d spring_branch_map(double m, double k, double c, double h, double kept) {
  Eigen::Matrix2d a;
  a(1, 0) = -h * k / m;
  a(1, 1) = kept * (1.0 - h * c / m);
  a(0, 0) = 1.0 + h * a(1, 0);
  a(0, 1) = h * a(1, 1);
  return a;
}

}  // namespace

int godot_3d_fit_steps(double omega, double zeta, double h) {
  const double hz = omega / (2.0 * std::numbers::pi);
  const double slow = zeta > 1.0 ? omega * (zeta - std::sqrt(zeta * zeta - 1.0)) : omega * std::max(zeta, 0.05);
  return std::clamp(static_cast<int>(std::min(6.0 / hz, 6.0 / slow) / h), 64, kGodot3DMaxFitSteps);
}

namespace {

// What Bullet does with (k, c): empty for values it cannot take (k <= 0, beyond float).
std::optional<Prediction> predict_bullet(double m, double k, double c, double h, double kept, int steps) {
  if (!(k > 0.0) || !(k < kFloatMax) || !(std::abs(c) < kFloatMax) || !(kept > 0.0)) return std::nullopt;
  const Prediction linear = predict_from_step_map(spring_branch_map(m, k, c, h, kept), h);
  const std::vector<double> x = godot_3d_bullet_trajectory(m, k, c, h, kept, steps);
  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v) && std::abs(v) < 1e6; })) {
    Prediction grows;
    grows.spectral_radius = std::numeric_limits<double>::infinity();
    grows.stable = false;
    return grows;
  }
  const ResponseFit fit = fit_response(x, h);
  // Gone within a few steps (nothing to fit): the linear part says how fast.
  if (!fit.frequency_hz || !fit.damping_ratio || !fit.z1 || !fit.z2) return linear;
  Prediction p;
  p.frequency_hz = fit.frequency_hz;
  p.damping_ratio = fit.damping_ratio;
  p.spectral_radius = std::max(std::abs(*fit.z1), std::abs(*fit.z2));
  p.stable = classify_spectral_radius(p.spectral_radius) != Verdict::unstable;
  return p;
}

// Newton on (ln k, c) for the asked response, the Jacobian from differences of 1e-3 (wide enough to step over
// the kinks the spring-dropping switch puts in the stepped response), at most kNewtonSteps steps of at most
// a factor 1.6 in k: a dozen predictions where solve_response's fine differences spend hundreds.
constexpr int kNewtonSteps = 12;

ResponseSolve newton_on_model(const std::function<std::optional<Prediction>(double, double)>& predict, const Target& t,
                              double k0, double c0) {
  const double asked_hz = t.omega / (2.0 * std::numbers::pi), c_scale = 1e-2 * t.effective_mass * t.omega;
  ResponseSolve out;
  auto residual = [&](double lk, double c, Prediction& p) -> std::optional<std::array<double, 2>> {
    const std::optional<Prediction> q = predict(std::exp(lk), c);
    if (!q || !q->stable || !q->frequency_hz || !q->damping_ratio || !(*q->frequency_hz > 0.0)) return std::nullopt;
    p = *q;
    return std::array<double, 2>{std::log(*q->frequency_hz / asked_hz), *q->damping_ratio - t.damping_ratio};
  };
  double lk = std::log(k0), c = c0;
  Prediction p;
  std::optional<std::array<double, 2>> r = residual(lk, c, p);
  for (int i = 0; r && i < kNewtonSteps; ++i) {
    out.p0 = std::exp(lk), out.p1 = c, out.prediction = p;
    out.frequency_error = std::expm1((*r)[0]), out.damping_error = (*r)[1];
    out.met = std::abs(out.frequency_error) <= kExactFrequencyTolerance && std::abs(out.damping_error) <= kExactDampingTolerance;
    if (std::abs((*r)[0]) < 0.1 * kExactFrequencyTolerance && std::abs((*r)[1]) < 0.1 * kExactDampingTolerance) break;
    const double dk = 1e-3, dc = 1e-3 * std::max(std::abs(c), c_scale);
    Prediction unused;
    const auto rk = residual(lk + dk, c, unused), rc = residual(lk, c + dc, unused);
    if (!rk || !rc) break;
    const double j00 = ((*rk)[0] - (*r)[0]) / dk, j10 = ((*rk)[1] - (*r)[1]) / dk;
    const double j01 = ((*rc)[0] - (*r)[0]) / dc, j11 = ((*rc)[1] - (*r)[1]) / dc;
    const double det = j00 * j11 - j01 * j10;
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) break;
    double step_k = -(j11 * (*r)[0] - j01 * (*r)[1]) / det, step_c = -(j00 * (*r)[1] - j10 * (*r)[0]) / det;
    const double limit = std::max(std::abs(step_k) / 0.5, std::abs(step_c) / (0.5 * std::max(std::abs(c), 10.0 * c_scale)));
    if (limit > 1.0) step_k /= limit, step_c /= limit;
    lk += step_k, c += step_c;
    r = residual(lk, c, p);
  }
  if (r) {
    out.p0 = std::exp(lk), out.p1 = c, out.prediction = p;
    out.frequency_error = std::expm1((*r)[0]), out.damping_error = (*r)[1];
    out.met = std::abs(out.frequency_error) <= kExactFrequencyTolerance && std::abs(out.damping_error) <= kExactDampingTolerance;
  }
  return out;
}

void refuse_godot_physics(EngineReport& out) {
  out.predicted = {std::nullopt, std::nullopt, 1.0, true};
  out.warnings.push_back({WarningCode::engine_refuses, 0.0, 0.0, kGodot3DModel.name,
                          "GodotPhysics 3-D in Godot 3.2 ignores Generic6DOFJoint's linear spring (its joints have "
                          "no springs): switch physics/3d/physics_engine to Bullet"});
  out.warnings.push_back({WarningCode::engine_inexact, 0.0, 0.0, kGodot3DModel.name,
                          "GodotPhysics 3-D has no joint spring to tune"});
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kGodot3DModel, values);
  if (values[kGodot3DPhysicsEngine] != 0.0) {
    refuse_godot_physics(out);
    return out;
  }
  const double m = t.effective_mass, h = t.dt, kept = godot_3d_bullet_velocity_kept(values, h);
  const double k = t.spring.stiffness, c = t.spring.damping;
  const int steps = t.omega > 0.0 ? godot_3d_fit_steps(t.omega, t.damping_ratio, h) : kGodot3DMaxFitSteps;

  // The plain export: softtune's k, c as the spring's stiffness and damping.
  report_lines::plain_export(out, predict_bullet(m, k, c, h, kept, steps), parameters_of(k, c), kGodot3DModel.name, k,
                             "the linear spring needs a stiffness above 0, and a body damping below 1 / h");

  if (!(t.omega > 0.0)) return out;
  // Exact: from the linear part's closed form (det = P, trace = S), then the solver on the stepped model.
  const double e = std::exp(-t.damping_ratio * t.omega * h);
  const double product = e * e;
  const double wd = t.omega * std::sqrt(std::abs(1.0 - t.damping_ratio * t.damping_ratio));
  const double sum = t.damping_ratio < 1.0 ? 2.0 * e * std::cos(wd * h) : 2.0 * e * std::cosh(wd * h);
  const double guess_k = m * (1.0 + product - sum) / (h * h);
  const double guess_c = kept > 0.0 ? m * (1.0 - product / kept) / h : 0.0;
  // The dropped-spring branch damps more than the linear part says, most where the damping is heavy; its
  // switch makes the response kinked in (k, c), so a few Newton steps with wide differences (newton_on_model)
  // from the closed form, and again from a softer, less damped guess when those stall; then, still unmet,
  // the fine-difference solver from four starts (up to some 20 ms: the model is not in engine_models(),
  // whose every report a tune computes; see docs/engines/godot_3d.md).
  std::optional<ResponseSolve> solve;
  if (guess_k > 0.0 && kept > 0.0) {
    auto predict = [&](double k_try, double c_try) { return predict_bullet(m, k_try, c_try, h, kept, steps); };
    for (const auto& [k_scale, c_scale] : {std::pair{1.0, 1.0}, std::pair{0.7, 0.5}}) {
      const ResponseSolve trial = newton_on_model(predict, t, k_scale * guess_k, c_scale * guess_c);
      if (!solve || trial.met) solve = trial;
      if (trial.met) break;
    }
    // Where Newton stalls on the kinks: Levenberg-Marquardt (solve_response), from four starts.
    for (const auto& [k_scale, c_scale] : {std::pair{1.0, 1.0}, std::pair{0.7, 0.5}, std::pair{0.5, 0.3},
                                           std::pair{0.85, 0.7}}) {
      if (solve->met) break;
      const ResponseSolve trial =
          solve_response(predict, t.omega, t.damping_ratio, k_scale * guess_k, c_scale * guess_c);
      if (trial.met) solve = trial;
    }
  }
  if (solve && solve->met && solve->prediction.stable) {
    out.exact = parameters_of(solve->p0, solve->p1);
    out.exact_predicted = solve->prediction;
    return out;
  }
  report_lines::inexact(out, solve ? std::optional<Prediction>(solve->prediction) : std::nullopt, t,
                        kGodot3DModel.name,
                        "no stiffness and damping make Bullet's spring row (semi-implicit, the spring dropped while "
                        "the damper outweighs it) meet this request at this step");
  return out;
}

}  // namespace

double godot_3d_bullet_velocity_kept(const SettingValues& values, double h) {
  const double damp = values[kGodot3DDefaultLinearDamp] + std::max(values[kGodot3DLinearDamp], 0.0);
  return std::clamp(1.0 - h * damp, 0.0, 1.0);
}

void godot_3d_bullet_step(double m, double k, double c, double h, double kept, double& x, double& v) {
  v *= kept;                              // btRigidBody::applyDamping
  const double f = -h * (k * x + c * v);  // get_limit_motor_info2: f = fs + fd (the body's side)
  const double fd = -h * c * v;
  const double impulse = (f * fd > 0.0 && std::abs(fd) > std::abs(f)) ? fd : f;  // the row driven to its limit
  v += impulse / m;
  x += h * v;                             // integrateTransforms
}

std::vector<double> godot_3d_bullet_trajectory(double m, double k, double c, double h, double kept, int steps) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(steps) + 1);
  double x = 1.0, v = 0.0;
  out.push_back(x);
  for (int i = 0; i < steps; ++i) {
    godot_3d_bullet_step(m, k, c, h, kept, x, v);
    out.push_back(x);
  }
  return out;
}

const EngineModel kGodot3DModel = {
    "godot_3d",
    "Godot 3.2.3 3-D: modules/bullet generic_6dof_joint_bullet.cpp, space_bullet.cpp, rigid_body_bullet.cpp; "
    "Bullet 2.89 btGeneric6DofSpring2Constraint.cpp get_limit_motor_info2, btDiscreteDynamicsWorld.cpp; "
    "GodotPhysics servers/physics/joints/generic_6dof_joint_sw.cpp",
    kSettings,
    report,
};

}  // namespace softtune::engines
