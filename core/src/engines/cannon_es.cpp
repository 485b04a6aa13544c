// cannon-es 0.20.0 (npm cannon-es 0.20.0), read in dist/cannon-es.js:
//   Spring            constructor (stiffness = options.stiffness || 100, damping = options.damping || 1: a typed
//                     0 becomes the default), applyForce (f = -k (|r| - restLength) - d (u . r_unit) along
//                     r_unit, u the relative velocity of the world anchors, torque r x f), called from the
//                     world's postStep event as its doc comment shows
//   Equation          constructor (setSpookParams(1e7, 4, 1 / 60)), setSpookParams(stiffness, relaxation,
//                     timeStep): a = 4 / (h (1 + 4 d)), b = 4 d / (1 + 4 d), eps = 4 / (h^2 k (1 + 4 d)) with
//                     h the timeStep passed, not the world's; computeC = G M^-1 G' + eps
//   ContactEquation   computeB: B = -g a - GW b - h GiMf, g the stretch along n
//   DistanceConstraint constructor (a ContactEquation, minForce -maxForce, maxForce 1e6), update (ri, rj
//                     half the distance along n from the centres: no torque)
//   GSSolver          solve: iterations (10) passes of deltalambda = invC (B - GWlambda - eps lambda), lambda
//                     clamped to [minForce, maxForce], then velocity += vlambda
//   World             internalStep: solver.solve, then v *= pow(1 - linearDamping, dt) (angular: angularDamping),
//                     preStep, Body.integrate (v += h f / m, x += h v: semi-implicit Euler), clearForces,
//                     postStep; step(dt) with no timeSinceLastCalled runs one internalStep; fixedStep(dt) calls
//                     step(dt, elapsed) (each internalStep is still dt)
//   Body              constructor (linearDamping 0.01, angularDamping 0.01)
//
// On effective mass m, x the stretch, v its rate, l = pow(1 - linearDamping, h), one world.step(h):
//   Spring (its force computed at the previous postStep from x, v):
//     v1 = l v - h (k x + c v) / m,  x1 = x + h v1
//   the map has det = l - h c / m and trace = 1 + det - h^2 k / m. Matching the poles (P = z1 z2, S = z1 + z2):
//     c = m (l - P) / h,  k = m (1 + P - S) / h^2,
//   closed form. A typed damping 0 becomes 1 (exact at zeta 0 and l = 1 types a tiny damping instead), and the
//   textbook c = 2 m zeta omega at 10 Hz / 0.5 and 60 fps makes det < 0: a pole that flips sign every step.
//   DistanceConstraint (one equation: the first Gauss-Seidel pass solves it, lambda = B / (1 / m + eps), so
//   the iterations change nothing), with g = 1 / (1 + eps m):
//     v1 = l (v - g (a x + b v)),  x1 = x + h v1
//   det = l (1 - b g), trace = 1 + det - h l a g. The SPOOK numbers are baked with the timeStep passed to
//   setSpookParams: stepping at another dt moves the frequency. Matching the poles for a bake step h0 gives,
//   with alpha = (1 + P - S) / (h l), beta = 1 - P / l: 1 + 4 d = 1 + 4 beta / (h0 alpha),
//   4 m / (h0^2 k) = 4 (1 - beta) / (h0 alpha) - 1 (k > 0 needs that above 0: stiffer is out of SPOOK's reach).
#include "softtune/engines/cannon_es.h"

#include <array>
#include <cmath>

#include "report_lines.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<std::string_view, 2> kJointChoices = {"spring", "distance"};
constexpr std::array<SettingSpec, 4> kSettings = {{
    {"joint", 0, 0, 1, true, kJointChoices, "",
     "spring: a Spring whose applyForce runs on the world's postStep; distance: a DistanceConstraint, its "
     "equation's setSpookParams"},
    {"linearDamping", 0.01, 0, 1, false, {}, "",
     "Body.linearDamping (angularDamping taken equal): v *= pow(1 - linearDamping, dt) every step"},
    {"spookTimeStep", 0, 0, 1, false, {}, "s",
     "the timeStep passed to setSpookParams (the Equation constructor bakes 1 / 60); 0: the world's step"},
    {"iterations", 10, 1, 1000, true, {}, "",
     "GSSolver.iterations; one equation converges in the first"},
}};

// The values Spring's constructor keeps: stiffness || 100, damping || 1.
double spring_stiffness_held(double k) { return k == 0.0 ? 100.0 : k; }
double spring_damping_held(double c) { return c == 0.0 ? 1.0 : c; }

// The smallest damping exact types where the poles ask for none: `damping || 1` would make 0 a damping of 1.
double nonzero_damping(double c, double m, double h) { return c == 0.0 ? 1e-9 * m / h : c; }

struct Step {
  double m, h, l;  // effective mass, world step, pow(1 - linearDamping, h)
  double bake;     // the SPOOK timeStep
};

Step step_of(const Target& t, const SettingValues& values) {
  const double bake = values[kCannonEsSpookTimeStep] > 0.0 ? values[kCannonEsSpookTimeStep] : t.dt;
  return {t.effective_mass, t.dt, std::pow(1.0 - values[kCannonEsLinearDamping], t.dt), bake};
}

Parameters spring_parameters(double k, double c) {
  return {{"Spring.stiffness", k, "N/m"}, {"Spring.damping", c, "N s/m"}};
}
Parameters spook_parameters(double k, double d) {
  return {{"setSpookParams.stiffness", k, "N/m"}, {"setSpookParams.relaxation", d, "steps"}};
}

Prediction predict_spring(const Step& s, const SettingValues& values, double k, double c) {
  return predict_from_step_map(cannon_es_spring_step_map(s.m, spring_stiffness_held(k), spring_damping_held(c), s.h,
                                                         values[kCannonEsLinearDamping]),
                               s.h);
}

Prediction predict_spook(const Step& s, const SettingValues& values, double k, double d) {
  return predict_from_step_map(cannon_es_spook_step_map(s.m, k, d, s.bake, s.h, values[kCannonEsLinearDamping]), s.h);
}

// The asked poles through exact softness (core/exact_softness.h): P = z1 z2 and 1 + P - S, from its k', c'
// (k' = m (1 + P - S) / (P h^2), c' + h k' = m (1 - P) / (P h)).
struct Poles {
  double product, one_minus_product;
  bool ok;
};
Poles asked_poles(const Target& t) {
  const ExactSpring e = exact_spring(t.effective_mass, t.omega, t.damping_ratio, t.dt);
  if (!e.finite) return {0.0, 0.0, false};
  const double m = t.effective_mass, h = t.dt;
  const double p = 1.0 / (1.0 + (e.spring.damping + h * e.spring.stiffness) * h / m);
  return {p, e.spring.stiffness * p * h * h / m, std::isfinite(p) && p > 0.0};
}

// Gives `exact` when its prediction meets the request, or is the nearest legal within the conformance bars.
void give_exact(EngineReport& out, const Target& t, Parameters exact, const std::optional<Prediction>& p,
                std::string_view reason) {
  const bool met = p && p->stable && meets_response(*p, t.omega, t.damping_ratio);
  if (met || (p && within_nearest(*p, t.omega, t.damping_ratio))) {
    out.exact = std::move(exact);
    out.exact_predicted = *p;
  }
  if (!met) report_lines::inexact(out, p, t, kCannonEsModel.name, reason);
}

void report_spring(EngineReport& out, const Target& t, const SettingValues& values, const Step& s) {
  const double k = t.spring.stiffness, c = t.spring.damping;
  report_lines::plain_export(out, predict_spring(s, values, k, c), spring_parameters(k, c), kCannonEsModel.name, k, "");
  if (k == 0.0 || c == 0.0) {
    out.warnings.push_back({WarningCode::engine_refuses, k == 0.0 ? k : c, 0.0, kCannonEsModel.name,
                            k == 0.0 ? "Spring keeps stiffness || 100: predicted is stiffness 100"
                                     : "Spring keeps damping || 1: a typed 0 is a damping of 1 N s/m, as predicted"});
  }
  if (!(t.omega > 0.0)) return;
  const Poles z = asked_poles(t);
  if (!z.ok) return report_lines::inexact(out, std::nullopt, t, kCannonEsModel.name, "the poles are too fast for the step");
  const double exact_k = s.m * z.one_minus_product / (s.h * s.h);
  const double exact_c = nonzero_damping(s.m * (s.l - z.product) / s.h, s.m, s.h);
  give_exact(out, t, spring_parameters(exact_k, exact_c), predict_spring(s, values, exact_k, exact_c),
             "the semi-implicit step cannot place these poles");
}

void report_distance(EngineReport& out, const Target& t, const SettingValues& values, const Step& s) {
  // The plain export: SPOOK's stiffness k and relaxation d = c / (k h0) steps (damping time c / k), baked with h0.
  const double k = t.spring.stiffness, d = t.spring.damping / (k * s.bake);
  report_lines::plain_export(out, predict_spook(s, values, k, d), spook_parameters(k, d), kCannonEsModel.name, k, "");
  if (!(t.omega > 0.0)) return;
  const Poles z = asked_poles(t);
  if (!z.ok || !(s.l > 0.0)) {
    return report_lines::inexact(out, std::nullopt, t, kCannonEsModel.name,
                                 "the poles are too fast for the step, or linearDamping 1 stops the body");
  }
  const double alpha = z.one_minus_product / (s.h * s.l);
  double beta = 1.0 - z.product / s.l;
  // Less damping than linearDamping gives needs beta < 0, a negative relaxation; 1 + 4 d must stay above 0
  // (a and eps keep their sign): below that, the nearest legal is relaxation 0 (no SPOOK damping at all).
  const bool undamped_floor = !(1.0 + 4.0 * beta / (s.bake * alpha) > 0.0);
  if (undamped_floor) beta = 0.0;
  const double big_d = 1.0 + 4.0 * beta / (s.bake * alpha);
  const double q = 4.0 * (1.0 - beta) / (s.bake * alpha) - 1.0;
  if (!(q > 0.0) || !std::isfinite(q)) {
    return report_lines::inexact(out, std::nullopt, t, kCannonEsModel.name,
                                 "SPOOK cannot reach a spring this stiff at this setSpookParams timeStep (it would "
                                 "need stiffness above infinity): bake with a shorter timeStep");
  }
  const double exact_k = 4.0 * s.m / (s.bake * s.bake * q), exact_d = (big_d - 1.0) / 4.0;
  give_exact(out, t, spook_parameters(exact_k, exact_d), predict_spook(s, values, exact_k, exact_d),
             undamped_floor ? "linearDamping damps more than asked, and cancelling it needs a relaxation below "
                              "-1/4 (1 + 4 relaxation <= 0): the nearest is relaxation 0"
                            : "the SPOOK step cannot place these poles");
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kCannonEsModel, values);
  const Step s = step_of(t, values);
  if (static_cast<int>(values[kCannonEsJoint]) == kCannonEsDistance) {
    report_distance(out, t, values, s);
  } else {
    report_spring(out, t, values, s);
  }
  return out;
}

}  // namespace

// World.internalStep with the Spring's force from the previous postStep (see the top of this file):
//   v1 = l v - h (k x + c v) / m,  x1 = x + h v1
Eigen::Matrix2d cannon_es_spring_step_map(double m, double k, double c, double dt, double linear_damping) {
  const double l = std::pow(1.0 - linear_damping, dt);
  Eigen::Matrix2d a;
  a(1, 0) = -dt * k / m;
  a(1, 1) = l - dt * c / m;
  a(0, 0) = 1.0 + dt * a(1, 0);
  a(0, 1) = dt * a(1, 1);
  return a;
}

// GSSolver.solve on the one equation, then the damping and Body.integrate:
//   v1 = l (v - g (a x + b v)),  g = 1 / (1 + eps m),  x1 = x + h v1
Eigen::Matrix2d cannon_es_spook_step_map(double m, double stiffness, double relaxation, double spook_dt, double dt,
                                         double linear_damping) {
  const double l = std::pow(1.0 - linear_damping, dt);
  const double big_d = 1.0 + 4.0 * relaxation;
  const double a_spook = 4.0 / (spook_dt * big_d), b_spook = 4.0 * relaxation / big_d;
  const double eps = 4.0 / (spook_dt * spook_dt * stiffness * big_d);
  const double g = 1.0 / (1.0 + eps * m);
  Eigen::Matrix2d a;
  a(1, 0) = -l * g * a_spook;
  a(1, 1) = l * (1.0 - g * b_spook);
  a(0, 0) = 1.0 + dt * a(1, 0);
  a(0, 1) = dt * a(1, 1);
  return a;
}

const EngineModel kCannonEsModel = {
    "cannon_es",
    "cannon-es 0.20.0 (npm cannon-es 0.20.0): dist/cannon-es.js Spring (constructor, applyForce), Equation "
    "(setSpookParams, computeC), ContactEquation.computeB, DistanceConstraint, GSSolver.solve, World "
    "(internalStep, step, fixedStep), Body.integrate",
    kSettings,
    report,
};

}  // namespace softtune::engines
