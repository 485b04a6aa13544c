// Godot 3.2.3 (Debian's godot3-server 3.2.3-stable, real_t float), GodotPhysics 2-D, read in
// godotengine/godot (3.2 branch) servers/physics_2d:
//   physics_2d_server_sw.cpp  Physics2DServerSW::init: iterations = 8; step: stepper->step(space, p_step,
//                             iterations) for each active space
//   step_2d_sw.cpp            Step2DSW::step: integrate_forces for every active body, then setup() of every
//                             constraint, then p_iterations passes of solve(), then integrate_velocities
//   body_2d_sw.cpp            Body2DSW::integrate_forces: damp = 1 - p_step linear_damp (0 when negative),
//                             linear_velocity *= damp (the body's linear_damp, or the area's -- the project's
//                             physics/2d/default_linear_damp, 0.1 -- when the body's is -1); integrate_velocities:
//                             pos += linear_velocity p_step (the velocity after the solve)
//   joints_2d_sw.cpp          DampedSpringJoint2DSW::setup: n_mass = 1 / k_scalar (the effective mass),
//                             target_vrn = 0, v_coef = 1 - exp(-damping p_step k_scalar), the spring impulse
//                             (rest_length - dist) stiffness p_step applied at once; solve: vrn = normal
//                             relative velocity - target_vrn, v_damp = -vrn v_coef, target_vrn = vrn + v_damp,
//                             the impulse v_damp n_mass applied
//   scene/2d/joints_2d.cpp    DampedSpringJoint2D: stiffness and damping passed as typed (the inspector's
//                             0.1-64 and 0.01-16 ranges are property hints; the setters do not clamp)
//   joints_2d_sw.cpp          PinJoint2DSW::setup: K = the anchor's inverse-mass tensor + softness on its
//                             diagonal, M = K^-1, bias = -(gB - gA) b / h with b the joint's bias or, when 0,
//                             the space's constraint_bias (0.2), the accumulated impulse P re-applied; solve:
//                             impulse = M (bias - rel_vel - softness P), P += impulse
//
// The PinJoint2D: on one body the first solve pass leaves v + b x / h - s P = 0 (M is K's exact inverse), so
// later passes add nothing and the step is the soft constraint of Catto's GDC 2011 talk with gamma = s and
// beta = b: implicit Euler on k = b / (h^2 s), c = (1 - b) / (h s), after the damping v *= D
// (soft_substeps.h substep_map). A typed bias of 0 is the space's 0.2, so beta = 0 cannot be typed.
//
// Chipmunk's cpDampedSpring (which this joint ports) computes vrn - target_vrn only once its target holds the
// velocity it left; Godot's solve subtracts target_vrn from the measured velocity instead, so on the pass
// after a drag vrn = 0, v_damp = 0 and target_vrn is reset to 0, and the next pass drags again. Of the 8
// passes, 4 drag: the velocity is scaled by (1 - v_coef)^4 = exp(-4 damping h / m), four times the drag
// typed -- what issue 33 measured (4.0-4.07x).
//
// On effective mass m, x the stretch, v its rate (a static anchor), one step of h:
//   v' = D v,  D = max(0, 1 - h linear_damp)          integrate_forces
//   v'' = v' - h k x / m                              setup's spring impulse, from the position at the start
//   v1 = E v'',  E = exp(-4 c h / m)                  the 8 solve passes
//   x1 = x + h v1                                     integrate_velocities
// det = D E, trace = 1 + D E - h^2 E k / m. Matching the poles z1, z2 = exp(s h) (P = z1 z2, S = z1 + z2):
//   c = -m ln(P / D) / (4 h) = m (2 zeta omega + ln(D) / h) / 4,   k = D m (1 + P - S) / (P h^2) = D k'
// with k' exact softness's stiffness (core/exact_softness.h): closed form whenever the poles exist and D > 0.
#include "softtune/engines/godot_2d.h"

#include <array>
#include <cmath>
#include <numbers>

#include "report_lines.h"
#include "soft_substeps.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

double velocity_kept_of(double linear_damp, double h) { return std::max(0.0, 1.0 - h * linear_damp); }

constexpr std::array<std::string_view, 2> kJoints = {"DampedSpringJoint2D", "PinJoint2D"};
constexpr std::array<SettingSpec, 2> kSettings = {{
    {"linear_damp", 0.1, 0, 1e6, false, {}, "1/s",
     "RigidBody2D linear_damp and angular_damp in effect (-1 takes the project's default_linear_damp, 0.1): "
     "v *= 1 - linear_damp h each step"},
    {"joint", 0, 0, 1, true, kJoints, "",
     "DampedSpringJoint2D (stiffness, damping) or PinJoint2D (softness, bias: Catto's soft constraint)"},
}};

Parameters pin_parameters_of(double softness, double bias) {
  return {{"PinJoint2D.softness", softness, "1/kg"}, {"PinJoint2D.bias", bias, ""}};
}

// softness = gamma = 1 / (h (c + h k)), bias = beta = h k / (c + h k); empty when c + h k <= 0 (no softness
// to type) or the bias would be 0 (typed 0 is the space's 0.2).
std::optional<std::pair<double, double>> pin_values(double k, double c, double h) {
  const double d = c + h * k;
  if (!(d > 0.0) || !(k > 0.0) || !std::isfinite(d)) return std::nullopt;
  return std::pair{1.0 / (h * d), h * k / d};
}

std::optional<Prediction> predict_pin(double m, double softness, double bias, double h, double linear_damp) {
  if (!(softness > 0.0) || !(bias > 0.0) || !(velocity_kept_of(linear_damp, h) > 0.0)) return std::nullopt;
  return predict_from_step_map(godot_2d_pin_step_map(m, softness, bias, h, linear_damp), h);
}

// The PinJoint2D report: the plain export is softtune's spring as softness and bias; exact is exact softness
// corrected for the damping (soft_substeps::exact_scaled), where c + h k stays positive.
EngineReport pin_report(const Target& t, const SettingValues& values, EngineReport out) {
  const double m = t.effective_mass, h = t.dt, damp = values[kGodot2DLinearDamp];
  const std::optional<std::pair<double, double>> plain = pin_values(t.spring.stiffness, t.spring.damping, h);
  report_lines::plain_export(out, plain ? predict_pin(m, plain->first, plain->second, h, damp) : std::nullopt,
                             plain ? pin_parameters_of(plain->first, plain->second) : Parameters{}, kGodot2DModel.name,
                             t.spring.damping + h * t.spring.stiffness,
                             "PinJoint2D's softness = 1 / (h (c + h k)) and bias = h k / (c + h k) need k > 0 and "
                             "c + h k > 0 (and a body damp below 1 / h)");
  if (!(t.omega > 0.0)) return out;
  const ExactSpring closed = exact_spring(m, t.omega, t.damping_ratio, h);
  const soft_substeps::Spring s =
      soft_substeps::exact_scaled(m, closed.spring.stiffness, closed.spring.damping, h, velocity_kept_of(damp, h));
  const std::optional<std::pair<double, double>> exact = closed.finite ? pin_values(s.k, s.c, h) : std::nullopt;
  const std::optional<Prediction> p = exact ? predict_pin(m, exact->first, exact->second, h, damp) : std::nullopt;
  if (p && p->stable && meets_response(*p, t.omega, t.damping_ratio)) {
    out.exact = pin_parameters_of(exact->first, exact->second);
    out.exact_predicted = *p;
    return out;
  }
  report_lines::inexact(out, p, t, kGodot2DModel.name,
                        closed.clamped_to_nyquist ? "the asked frequency is above the step's Nyquist limit"
                                                  : "this damping needs c + h k <= 0: no softness to type (light "
                                                    "damping against the body's linear_damp)");
  return out;
}

Parameters parameters_of(double k, double c) {
  return {{"DampedSpringJoint2D.stiffness", k, "N/m"}, {"DampedSpringJoint2D.damping", c, "N s/m"}};
}

// What Godot does with (k, c): empty for a stiffness that is no spring, a value that is not a finite float,
// or a body damp that stops the body every step (D = 0).
std::optional<Prediction> predict_spring(double m, double k, double c, double h, double linear_damp) {
  constexpr double kFloatMax = 3.4028234663852886e38;
  if (!(k > 0.0) || !(k < kFloatMax) || !(std::abs(c) < kFloatMax) || !(velocity_kept_of(linear_damp, h) > 0.0)) {
    return std::nullopt;
  }
  return predict_from_step_map(godot_2d_step_map(m, k, c, h, linear_damp), h);
}

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kGodot2DModel, values);
  if (values[kGodot2DJoint] != 0.0) return pin_report(t, values, std::move(out));
  const double m = t.effective_mass, h = t.dt, damp = values[kGodot2DLinearDamp];
  const double k = t.spring.stiffness, c = t.spring.damping;

  // The plain export: softtune's k, c typed into the joint's own fields.
  report_lines::plain_export(out, predict_spring(m, k, c, h, damp), parameters_of(k, c), kGodot2DModel.name, k,
                             "a DampedSpringJoint2D needs a stiffness above 0, and the body's linear_damp below 1 / h "
                             "(at or above it integrate_forces stops the body every step)");

  if (!(t.omega > 0.0)) return out;
  const double kept = velocity_kept_of(damp, h);
  const ExactSpring closed = exact_spring(m, t.omega, t.damping_ratio, h);
  std::optional<Prediction> p;
  double exact_k = 0.0, exact_c = 0.0;
  if (closed.finite && kept > 0.0) {
    exact_k = kept * closed.spring.stiffness;
    exact_c = m * (2.0 * t.damping_ratio * closed.omega + std::log(kept) / h) / kGodot2DDragPasses;
    p = predict_spring(m, exact_k, exact_c, h, damp);
  }
  if (p && p->stable && meets_response(*p, t.omega, t.damping_ratio)) {
    out.exact = parameters_of(exact_k, exact_c);
    out.exact_predicted = *p;
    return out;
  }
  report_lines::inexact(out, p, t, kGodot2DModel.name,
                        closed.clamped_to_nyquist ? "the asked frequency is above the step's Nyquist limit"
                        : kept > 0.0              ? "the poles are too fast for the step to represent"
                                                  : "linear_damp h >= 1 stops the body every step");
  return out;
}

}  // namespace

// Step2DSW::step for one body on one DampedSpringJoint2D (see the top of this file):
//   v1 = E (D v - h (k / m) x),  x1 = x + h v1,  D = max(0, 1 - h linear_damp),  E = exp(-4 c h / m)
Eigen::Matrix2d godot_2d_step_map(double m, double k, double c, double h, double linear_damp) {
  const double d = velocity_kept_of(linear_damp, h), e = std::exp(-kGodot2DDragPasses * c * h / m), w2 = k / m;
  Eigen::Matrix2d a;
  a(1, 0) = -e * h * w2;
  a(1, 1) = e * d;
  a(0, 0) = 1.0 + h * a(1, 0);
  a(0, 1) = h * a(1, 1);
  return a;
}

// Step2DSW::step for one body on one PinJoint2D: integrate_forces' damp, then the soft constraint's substep.
Eigen::Matrix2d godot_2d_pin_step_map(double m, double softness, double bias, double h, double linear_damp) {
  // gamma = s, beta = b <=> k = b / (h^2 s), c = (1 - b) / (h s) (softness.h's inverse).
  return soft_substeps::substep_map(m, bias / (h * h * softness), (1.0 - bias) / (h * softness), h,
                                    velocity_kept_of(linear_damp, h));
}

const EngineModel kGodot2DModel = {
    "godot_2d",
    "Godot 3.2.3 GodotPhysics 2-D: joints_2d_sw.cpp DampedSpringJoint2DSW and PinJoint2DSW setup and solve, "
    "step_2d_sw.cpp "
    "Step2DSW::step, body_2d_sw.cpp integrate_forces and integrate_velocities, physics_2d_server_sw.cpp "
    "iterations = 8",
    kSettings,
    report,
};

}  // namespace softtune::engines
