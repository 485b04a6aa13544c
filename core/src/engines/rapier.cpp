// Rapier 0.35 (the engine inside npm @dimforge/rapier2d-compat / rapier3d-compat 0.21.0), read in src/dynamics:
//   joint/motor_model.rs            MotorModel (AccelerationBased default, ForceBased), combine_coefficients:
//                                   erp_inv_dt = k / (h k + c); AccelerationBased cfm_coeff = 1 / (h^2 k + h c),
//                                   ForceBased cfm_gain = 1 / (h^2 k + h c) (utils::inv(0) = 0)
//   joint/generic_joint.rs          JointMotor::motor_params (h = the substep's dt), defaults
//   joint/spring_joint.rs           SpringJoint::new: a coupled LinX motor, ForceBased
//   solver/joint_constraint/joint_constraint_helper.rs  motor_linear, motor_linear_coupled: rhs = rhs_wo_bias
//                                   = (dist - target) erp_inv_dt - target_vel; finalize_constraints:
//                                   cfm_gain = dot_jj cfm_coeff + cfm_gain, inv_lhs = 1 / (dot_jj + cfm_gain)
//   solver/joint_constraint/joint_velocity_constraint.rs  solve_generic: P += inv_lhs (J v + rhs - cfm_gain P),
//                                   remove_bias_from_rhs (a motor row keeps its spring term)
//   solver/joint_constraint/joint_constraint_builder.rs   update: rows rebuilt from the poses every substep,
//                                   impulses from zero unless warmstart_joints
//   solver/staged_island_solver/worker.rs, solve.rs, init.rs  the substep loop: num_substeps =
//                                   num_solver_iterations + the body's additional_solver_iterations, each:
//                                   forces, row update, num_internal_pgs_iterations biased passes, integrate
//                                   positions, num_internal_stabilization_iterations unbiased passes; damping
//                                   once per step at writeback (rigid_body_components.rs apply_damping)
//   integration_parameters.rs       num_solver_iterations = 4, num_internal_pgs_iterations = 1
//
// So a motor row with dot_jj = 1 / m_eff is Erin Catto's soft constraint with softness
// gamma = 1 / (h (h k_f + c_f)) and bias k_f / (h k_f + c_f) C, where (k_f, c_f) = (k, c) for ForceBased and
// m_eff (k, c) for AccelerationBased. Its first pass converges; the unbiased pass re-solves the same row with
// the same rhs (rebuilt only at the next substep) and adds nothing; further PGS passes and joint warm starts
// add nothing either. Each substep is implicit Euler on (m_eff, k_f, c_f) at h = dt / substeps
// (soft_substeps.h): the solver iterations are substeps. Linear damping d scales v by 1 / (1 + dt d) once per
// step. Where h k + c = 0 utils::inv gives 0 and the motor locks the velocity; below it the compliance is
// negative: both are refused.
#include "softtune/engines/rapier.h"

#include <array>
#include <cmath>

#include "soft_substeps.h"
#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kMotorModels = {"AccelerationBased", "ForceBased"};
constexpr std::array<SettingSpec, 5> kSettings = {{
    {"numSolverIterations", 4, 1, 1024, true, {}, "",
     "IntegrationParameters::num_solver_iterations: the substeps of each World::step"},
    {"numInternalPgsIterations", 1, 1, 1024, true, {}, "",
     "IntegrationParameters::num_internal_pgs_iterations; one motor row converges in the first"},
    {"motorModel", 0, 0, 1, true, kMotorModels, "",
     "JointMotor::model: stiffness and damping per unit effective mass, or forces"},
    {"additionalSolverIterations", 0, 0, 1024, true, {}, "",
     "RigidBodyDesc::setAdditionalSolverIterations: extra substeps for the body's island"},
    {"linearDamping", 0, 0, 1e6, false, {}, "1/s",
     "RigidBodyDesc::setLinearDamping (and angular): v /= 1 + dt damping once per step"},
}};

constexpr double kFloatMax = 3.4028234663852886e38;

struct Step {
  double m, h, dt, damping_scale;
  int n;
  bool acceleration;
};

Step step_of(const Target& t, const SettingValues& values) {
  const int n = static_cast<int>(values[kRapierNumSolverIterations] + values[kRapierAdditionalSolverIterations]);
  return {t.effective_mass, t.dt / n, t.dt, 1.0 / (1.0 + t.dt * values[kRapierLinearDamping]), n,
          values[kRapierMotorModel] == 0.0};
}

Eigen::Matrix2d step_map(const Step& s, double k, double c) {
  Eigen::Matrix2d a = soft_substeps::power(soft_substeps::substep_map(s.m, k, c, s.h, 1.0), s.n);
  a.row(1) *= s.damping_scale;
  return a;
}

// What the engine does with the force-based (k, c): empty where it refuses them.
bool legal(const Step& s, double k, double c) {
  const double scale = s.acceleration ? 1.0 / s.m : 1.0;  // what is typed, which the engine holds in f32
  return k > 0.0 && c + s.h * k >= kRapierFloatMargin * s.h * k && k * scale <= kFloatMax &&
         std::abs(c) * scale <= kFloatMax;
}

std::optional<Prediction> predict_spring(const Step& s, double k, double c) {
  if (!legal(s, k, c)) return std::nullopt;
  return predict_from_step_map(step_map(s, k, c), s.dt);
}

// What the engine does with a refused (k, c), k > 0 and finite in f32: combine_coefficients computes, in
// f32 at the substep h from the typed stiffness k_t and damping c_t (per unit mass for AccelerationBased),
//   erp_inv_dt = k_t inv(h k_t + c_t),  cfm = inv(h h k_t + h c_t)      (utils::inv(0) = 0)
// and the first pass gives v1 = v - g (v + erp_inv_dt x), g = dot_jj / (dot_jj + cfm_gain) with
// cfm_gain = dot_jj cfm (AccelerationBased) or cfm (ForceBased), dot_jj = 1 / m_eff. The two sums round
// on their own: where they are a few ulp of h k (exact mode at zeta 0, one substep per softtune step) their
// ratio, not h, sets the spring, and a sum that rounds to 0 locks the velocity (cfm 0) or drops the spring
// (erp 0). Below zero the same algebra is implicit Euler with the negative damping, which grows.
Prediction predict_refused(const Step& s, double k, double c) {
  const double scale = s.acceleration ? 1.0 / s.m : 1.0;
  const float hf = static_cast<float>(static_cast<float>(s.dt) / static_cast<float>(s.n));
  const float kf = static_cast<float>(k * scale), cf = static_cast<float>(c * scale);
  const float hk = hf * kf, hhk = hf * hf * kf, hc = hf * cf;
  const float sum1 = hk + cf, sum2 = hhk + hc;
  auto inv = [](float x) { return x == 0.0f ? 0.0f : 1.0f / x; };
  const double erp = static_cast<double>(kf * inv(sum1));
  const double cfm = static_cast<double>(inv(sum2));
  const double dot_jj = 1.0 / s.m;
  const double cfm_gain = s.acceleration ? dot_jj * cfm : cfm;
  const double g = dot_jj / (dot_jj + cfm_gain);
  const double h = static_cast<double>(hf);
  Eigen::Matrix2d sub;
  sub(1, 0) = -g * erp;
  sub(1, 1) = 1.0 - g;
  sub(0, 0) = 1.0 + h * sub(1, 0);
  sub(0, 1) = h * sub(1, 1);
  Eigen::Matrix2d a = soft_substeps::power(sub, s.n);
  a.row(1) *= s.damping_scale;
  return predict_from_step_map(a, s.dt);
}

Parameters parameters_of(const Step& s, double k, double c) {
  if (s.acceleration) {
    return {{"JointMotor::model", 0.0, "", kMotorModels[0]},
            {"JointMotor::stiffness", k / s.m, "1/s^2"},
            {"JointMotor::damping", c / s.m, "1/s"}};
  }
  return {{"JointMotor::model", 0.0, "", kMotorModels[1]},
          {"JointMotor::stiffness", k, "N/m"},
          {"JointMotor::damping", c, "N s/m"}};
}

double frequency_error(const Prediction& p, const Target& t) {
  return *p.frequency_hz / frequency_from_angular(t.omega) - 1.0;
}

bool meets(const Prediction& p, const Target& t) { return meets_response(p, t.omega, t.damping_ratio); }

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kRapierModel, values);
  const Step s = step_of(t, values);
  const double k = t.spring.stiffness, c = t.spring.damping;
  out.parameters = parameters_of(s, k, c);
  if (const std::optional<Prediction> p = predict_spring(s, k, c)) {
    out.predicted = *p;
    if (!p->stable) out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kRapierModel.name});
  } else if (k > 0.0 && k * (s.acceleration ? 1.0 / s.m : 1.0) <= kFloatMax &&
             std::abs(c) * (s.acceleration ? 1.0 / s.m : 1.0) <= kFloatMax) {
    // Refused, yet the engine runs it: `predicted` is what it does.
    out.predicted = predict_refused(s, k, c);
    out.warnings.push_back({WarningCode::engine_refuses, c + s.h * k, 0.0, kRapierModel.name,
                            "the motor needs damping + h stiffness > 0 at the substep h: combine_coefficients "
                            "inverts h stiffness + damping and h^2 stiffness + h damping, each rounded in f32; "
                            "`predicted` is the step with those (a locked or undamped motor near 0, a growing "
                            "one below)"});
    if (!out.predicted.stable) {
      out.warnings.push_back({WarningCode::engine_unstable, out.predicted.spectral_radius, 1.0, kRapierModel.name});
    }
  } else {
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, c + s.h * k, 0.0, kRapierModel.name,
                            "the motor needs stiffness > 0 and damping + h stiffness > 0 at the substep h: "
                            "combine_coefficients inverts h^2 stiffness + h damping, and at 0 the motor locks"});
  }
  if (!(t.omega > 0.0)) return out;

  // Exact: softtune's exact spring at the substep h (closed form); where zeta near 0 needs c + h k <= 0, the
  // least-damped spring the engine takes; with linear damping (not the default) the
  // solver corrects what spreading it over the substeps misses.
  const ExactSpring closed = exact_spring(s.m, t.omega, t.damping_ratio, s.h);
  std::optional<soft_substeps::Spring> candidate;
  if (closed.finite && !closed.clamped_to_nyquist) {
    // The step's damping scale, spread over the substeps as if each scaled by b^(1/n): exact for b = 1 (the
    // default), a close start for the solver otherwise.
    const double a = s.damping_scale == 1.0 ? 1.0 : std::pow(s.damping_scale, 1.0 / s.n);
    candidate = soft_substeps::exact_scaled(s.m, closed.spring.stiffness, closed.spring.damping, s.h, a);
    if (!legal(s, candidate->k, candidate->c)) {
      candidate = soft_substeps::least_damped(s.m, t.omega, s.h, a, 2.0 * kRapierFloatMargin);
    }
  }
  std::optional<Prediction> e;
  if (candidate && s.damping_scale == 1.0 && legal(s, candidate->k, candidate->c) &&
      candidate->k == closed.spring.stiffness) {
    e = soft_substeps::matched_prediction(t.omega, t.damping_ratio, s.dt);  // the closed form, exact by construction
  } else if (candidate) {
    e = predict_spring(s, candidate->k, candidate->c);
  }
  // The solver aims ten times inside the tolerance, as solve_response does.
  const bool tight = e && meets_response(*e, t.omega, t.damping_ratio, 0.1);
  if (candidate && !tight && s.damping_scale != 1.0) {
    const ResponseSolve solve = solve_response(
        [&](double k_try, double c_try) { return predict_spring(s, k_try, c_try); }, t.omega, t.damping_ratio,
        candidate->k, candidate->c);
    if (solve.met || !e || !meets(*e, t)) {  // keep a candidate that met over a solve that did not
      candidate = soft_substeps::Spring{solve.p0, solve.p1};
      e = solve.prediction;
      if (!solve.met && !solve.prediction.frequency_hz) e.reset();
    }
  }
  if (e && meets(*e, t)) {
    out.exact = parameters_of(s, candidate->k, candidate->c);
    out.exact_predicted = *e;
  } else if (e && e->frequency_hz && e->damping_ratio) {
    // The least-damped motor (or the solver's nearest) is given when within the nearest bars.
    const bool nearest = within_nearest(*e, t.omega, t.damping_ratio) && legal(s, candidate->k, candidate->c);
    if (nearest) {
      out.exact = parameters_of(s, candidate->k, candidate->c);
      out.exact_predicted = *e;
    }
    out.warnings.push_back({WarningCode::engine_inexact, frequency_error(*e, t), *e->damping_ratio - t.damping_ratio,
                            kRapierModel.name,
                            nearest ? "each substep is implicit Euler, which always damps, and linear damping adds "
                                      "to it: `exact` is the nearest legal motor"
                                    : "each substep is implicit Euler, which always damps, and linear damping adds to it: "
                                      "less damping needs damping + h stiffness <= 0, where the motor locks"});
  } else {
    out.warnings.push_back({WarningCode::engine_inexact, 0.0, 0.0, kRapierModel.name,
                            "no motor reaches the asked poles: they pass the substep's Nyquist limit"});
  }
  return out;
}

}  // namespace

// World::step of dt for one body on one motor row: n times
//   v = v - inv_lhs/m (v + erp_inv_dt x + cfm_gain P)   (solve_generic, first pass, converged)
//   x = x + h v                                         (integrate positions; the unbiased pass adds 0)
// then v = v / (1 + dt d)                               (apply_damping at writeback)
Eigen::Matrix2d rapier_step_map(double m, double k, double c, double dt, int substeps, double linear_damping) {
  Eigen::Matrix2d a = soft_substeps::power(soft_substeps::substep_map(m, k, c, dt / substeps, 1.0), substeps);
  a.row(1) *= 1.0 / (1.0 + dt * linear_damping);
  return a;
}

const EngineModel kRapierModel = {
    "rapier",
    "Rapier 0.35 (npm @dimforge/rapier2d-compat, rapier3d-compat 0.21.0): motor_model.rs, "
    "joint_constraint_helper.rs, joint_velocity_constraint.rs, joint_constraint_builder.rs, "
    "staged_island_solver/worker.rs",
    kSettings,
    report,
};

}  // namespace softtune::engines
