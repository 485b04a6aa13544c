// ODE 0.16 (Debian's libode-dev 0.16.2, built double: dCheckConfiguration("ODE_double_precision") = 1), read
// at the 0.16 release (thomasmarsh/ODE 89b2a525) in ode/src:
//   objects.cpp        dxWorld::dxWorld: global_erp = 0.2, global_cfm = 1e-10 (dDOUBLE; 1e-5 is dSINGLE's);
//                      dxQuickStepParameters: num_iterations = 20, w = 1.3
//   joints/dball.cpp   dxJointDBall::getInfo2: one row, J = unit direction between the anchors,
//                      rhs = fps erp (targetDistance - distance), cfm = the joint's dParamCFM
//   joints/ball.cpp    dxJointBall::getInfo2 / setBall (joint.cpp): three rows, rhs = fps erp (anchor2 -
//                      anchor1), each with the joint's dParamCFM
//   joints/joint.cpp   dxJointLimitMotor::addLimot: a slider stop row, rhs = -fps stop_erp limit_err,
//                      cfm = stop_cfm, and lo = -inf, hi = inf when lostop == histop (two-sided)
//   step.cpp           dxStepIsland (dWorldStep): rhs and cfm times 1/h (Stage2a), A = J invM J' with cfm on
//                      its diagonal (Stage2b), rhs = c/h - J (v/h + invM fe), dxSolveLCP (a direct LDLT solve
//                      for unbounded rows), v += h invM (J' lambda + fe), then dxStepBody
//   quickstep.cpp      dxQuickStepIsland (dWorldQuickStep): the same rhs and cfm/h (Stage2a-c), lambda = 0
//                      (Stage4a, WARM_STARTING off), Ad = w / (J invM J' + cfm/h) (Stage4LCP_AdComputation),
//                      num_iterations sweeps of lambda += Ad (rhs - cfm lambda - J fc)
//                      (Stage4LCP_IterationStep), v += h (fc + invM fe) (Stage5/6), then dxStepBody
//   util.cpp           dxStepBody: pos += h lvel with the new velocity (semi-implicit Euler)
// Neither setter checks its value (dWorldSetERP, dJointSetDBallParam, dxJointLimitMotor::set store it as
// given), so ERP above 1 is taken as typed: it is negative damping c = (1 - ERP) / CFM, which exact mode
// needs at light damping. The user guide's 0..1 range for ERP is advice, not a check.
//
// One row on effective mass m (a row no other row couples to: the dball's one row; the ball's and the
// slider's other rows have zero error and are orthogonal to it through M^-1), x the row's error, v its rate:
//   lambda* = (-erp x / h - v) / h / (1/m + cfm/h)     the force the direct solve returns
//   lambda  = rho lambda*,  rho = 1 (dWorldStep) or 1 - (1 - w)^N (dWorldQuickStep, N sweeps from 0)
//   v1 = v + h lambda / m,  x1 = x + h v1
// With rho = 1 that is the soft constraint gamma = CFM / h, beta = ERP: implicit Euler on k = ERP / (h CFM),
// c = (1 - ERP) / CFM (the user guide's ERP = h k / (h k + c), CFM = 1 / (h k + c)).
#include "softtune/engines/ode.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kStepperChoices = {"dWorldStep", "dWorldQuickStep"};
constexpr std::array<std::string_view, 3> kJointChoices = {"dball", "ball", "slider"};
constexpr std::array<SettingSpec, 4> kSettings = {{
    {"stepper", 0, 0, 1, true, kStepperChoices, "",
     "dWorldStep solves the rows exactly; dWorldQuickStep runs SOR sweeps"},
    {"dWorldSetQuickStepNumIterations", 20, 1, 10000, true, {}, "",
     "dWorldQuickStep's SOR sweeps per step (quickstep only)"},
    // SOR converges for 0 < w < 2; ODE does not check the value.
    {"dWorldSetQuickStepW", 1.3, 0.01, 1.99, false, {}, "", "dWorldQuickStep's over-relaxation (quickstep only)"},
    {"joint", 0, 0, 2, true, kJointChoices, "",
     "the joint carrying the row: dball (one row), ball (three), slider with lo = hi = 0 stops"},
}};

OdeJoint joint_of(const SettingValues& values) {
  return values.size() > kOdeJoint ? static_cast<OdeJoint>(static_cast<int>(values[kOdeJoint])) : OdeJoint::dball;
}

// The joint's own names for the row's ERP and CFM (dJointSet<Joint>Param's parameter).
Parameters parameters_of(OdeJoint joint, double erp, double cfm) {
  if (joint == OdeJoint::slider) {
    return {{"dParamStopERP", erp, ""}, {"dParamStopCFM", cfm, "m/(N s)"}, {"dParamLoStop", 0.0, "m"},
            {"dParamHiStop", 0.0, "m"}};
  }
  return {{"dParamERP", erp, ""}, {"dParamCFM", cfm, "m/(N s)"}};
}

// What ODE does with (erp, cfm); empty for values the model does not export: ERP <= 0 (no spring),
// CFM <= 0 (rigid, or A + CFM/h no longer positive for the LDLT solve), ERP above kOdeMaxErp.
std::optional<Prediction> predict_row(double m, double erp, double cfm, double h, double rho) {
  if (!(erp > 0.0) || !(erp <= kOdeMaxErp) || !(cfm > 0.0) || !std::isfinite(cfm)) return std::nullopt;
  return predict_from_step_map(ode_step_map(m, erp, cfm, h, rho), h);
}

bool meets(const Prediction& p, const Target& t) { return p.stable && meets_response(p, t.omega, t.damping_ratio); }

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kOdeModel, values);
  const OdeJoint joint = joint_of(values);
  const double m = t.effective_mass, h = t.dt, rho = ode_impulse_fraction(values);
  const double k = t.spring.stiffness, c = t.spring.damping;

  // The plain export (ode user guide, "Joint error and the error reduction parameter"):
  // ERP = h k / (h k + c), CFM = 1 / (h k + c).
  const double denominator = h * k + c;
  const double erp = h * k / denominator, cfm = 1.0 / denominator;
  if (const std::optional<Prediction> p = denominator > 0.0 ? predict_row(m, erp, cfm, h, rho) : std::nullopt) {
    out.parameters = parameters_of(joint, erp, cfm);
    out.predicted = *p;
    if (!p->stable) out.warnings.push_back({WarningCode::engine_unstable, p->spectral_radius, 1.0, kOdeModel.name});
  } else {
    out.predicted = {std::nullopt, std::nullopt, 1.0, true};
    out.warnings.push_back({WarningCode::engine_refuses, denominator, 0.0, kOdeModel.name,
                            "ERP = h k / (h k + c) and CFM = 1 / (h k + c) need k > 0 and h k + c > 0 "
                            "(and ERP at most 1e6): this spring has no ERP/CFM"});
  }

  if (!(t.omega > 0.0)) return out;
  // Exact, in closed form. The step map has det = 1 - G and trace = 2 - G - G ERP, G = rho h / (h + m CFM)
  // (ode_step_map), so the poles z1, z2 = exp(s h) need G = 1 - P, ERP = (1 - z1)(1 - z2) / (1 - P), P = z1 z2:
  // ERP is exact_spring's beta' whatever rho, and CFM = h (rho - 1 + P) / (m (1 - P)) = gamma' (rho - 1 + P) / P.
  // Zero damping needs P = 1, G = 0: no finite CFM, so exact aims at kOdeDampingFloor.
  const double zeta = std::max(t.damping_ratio, kOdeDampingFloor);
  const ExactSpring closed = exact_spring(m, t.omega, zeta, h);
  if (closed.finite && !closed.clamped_to_nyquist && closed.softness.kind == SoftnessKind::soft) {
    const double product = std::exp(-2.0 * zeta * t.omega * h);
    const double exact_cfm = closed.softness.gamma * ((rho - 1.0) + product) / product;
    const std::optional<Prediction> p = predict_row(m, closed.softness.beta, exact_cfm, h, rho);
    if (p && meets(*p, t)) {
      out.exact = parameters_of(joint, closed.softness.beta, exact_cfm);
      out.exact_predicted = *p;
      return out;
    }
  }
  // No closed form applies (above Nyquist, or the quick step's sweeps cannot remove 1 - P of the velocity
  // per step): the nearest (h k + c = 1 / CFM, ERP) the solver finds.
  const SpringConstants guess = spring_constants(m, t.omega, t.damping_ratio);
  const Softness guess_soft = softness_from_spring(guess.stiffness, guess.damping, h);
  const ResponseSolve solve = solve_response(
      [&](double inverse_cfm, double erp_try) { return predict_row(m, erp_try, 1.0 / inverse_cfm, h, rho); },
      t.omega, t.damping_ratio, 1.0 / guess_soft.gamma, guess_soft.beta);
  if (solve.met) {
    out.exact = parameters_of(joint, solve.p1, 1.0 / solve.p0);
    out.exact_predicted = solve.prediction;
  } else {
    out.warnings.push_back({WarningCode::engine_inexact, solve.frequency_error, solve.damping_error,
                            kOdeModel.name,
                            closed.clamped_to_nyquist
                                ? "the asked frequency is above the step's Nyquist limit"
                                : "dWorldQuickStep's sweeps apply at most 1 - (1 - w)^N of the impulse, which "
                                  "removes less velocity per step than this damping needs"});
  }
  return out;
}

}  // namespace

double ode_impulse_fraction(const SettingValues& values) {
  if (values.size() <= kOdeSorW || values[kOdeStepper] == 0.0) return 1.0;
  // quickstep.cpp dxQuickStepIsland_Stage4LCP_IterationStep on one row: delta = Ad (b - (a + cfm/h) lambda)
  // = w (lambda* - lambda), so lambda* - lambda shrinks by (1 - w) per sweep, from lambda = 0.
  return 1.0 - std::pow(1.0 - values[kOdeSorW], values[kOdeIterations]);
}

// dxStepIsland / dxQuickStepIsland for one body on a static world through one row:
//   a = 1/m (A = J invM J'), cfm/h on its diagonal, b = (fps erp (-x)) / h - v / h
//   lambda = rho b / (a + cfm/h)
//   v1 = v + h lambda / m = v - G (v + erp x / h),  G = rho (1/m) / (1/m + cfm/h) = rho h / (h + m cfm)
//   x1 = x + h v1                                   (dxStepBody)
Eigen::Matrix2d ode_step_map(double m, double erp, double cfm, double h, double rho) {
  const double gain = rho * h / (h + m * cfm);
  Eigen::Matrix2d a;
  a(1, 0) = -gain * erp / h;
  a(1, 1) = 1.0 - gain;
  a(0, 0) = 1.0 + h * a(1, 0);
  a(0, 1) = h * a(1, 1);
  return a;
}

const EngineModel kOdeModel = {
    "ode",
    "ODE 0.16.2 (double): step.cpp dxStepIsland, quickstep.cpp dxQuickStepIsland, joints/dball.cpp, "
    "joints/ball.cpp, joints/joint.cpp addLimot, objects.cpp defaults",
    kSettings,
    report,
};

}  // namespace softtune::engines
