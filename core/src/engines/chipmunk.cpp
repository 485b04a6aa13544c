// Chipmunk 7.0.3 (Debian's libchipmunk-dev, CP_USE_DOUBLES 1), read at the Chipmunk-7.0.3 tag of
// slembcke/Chipmunk2D in src:
//   cpSpaceStep.c     cpSpaceStep: integrate positions first (body->position_func), then each constraint's
//                     preStep, then the velocities (body->velocity_func with damping = cpfpow(space->damping,
//                     dt)), the cached impulses, and space->iterations passes of each constraint's applyImpulse
//   cpBody.c          cpBodyUpdatePosition: p += (v + v_bias) dt; cpBodyUpdateVelocity: v = v damping + (g +
//                     f / m) dt
//   cpDampedSpring.c  preStep: n and r from the positions just integrated, nMass = 1 / k_scalar (the effective
//                     mass), target_vrn = 0, v_coef = 1 - exp(-damping dt / nMass), and the spring impulse
//                     (restLength - dist) stiffness dt applied at once; applyImpulse: v_damp = (target_vrn -
//                     vrn) v_coef, target_vrn = vrn + v_damp, the impulse v_damp nMass applied;
//                     applyCachedImpulse does nothing
//   cpSpace.c         cpSpaceInit: iterations = 10, damping = 1
// Neither cpDampedSpringSetStiffness nor ...SetDamping checks its value.
//
// On effective mass m, x the spring's stretch, v its rate (a lone spring, a static anchor), one cpSpaceStep:
//   x1 = x + h v                                 cpBodyUpdatePosition, before the spring looks at x
//   v' = v - h k x1 / m                          preStep's spring impulse
//   v'' = d v',  d = damping^h                   cpBodyUpdateVelocity (gravity zero)
//   v1 = e v'',  e = exp(-c h / m)               the first applyImpulse: target_vrn = vrn (1 - v_coef); the
//                                                later passes find vrn == target_vrn and add nothing, so the
//                                                iteration count changes nothing for one spring
// The drag is exact exponential decay and the spring explicit on the new position: the step map has
// det = d e and trace = 1 + d e (1 - h^2 k / m). Matching the poles z1, z2 = exp(s h) (P = z1 z2, S = z1 + z2):
//   c = -m ln(P / d) / h = 2 zeta omega m + m ln(damping),   k = m (1 + P - S) / (P h^2),
// which is exact softness's k' (core/exact_softness.h): closed form whenever the poles exist.
#include "softtune/engines/chipmunk.h"

#include <array>
#include <cmath>

#include "report_lines.h"
#include "softtune/exact_softness.h"

namespace softtune::engines {
namespace {

constexpr std::array<SettingSpec, 2> kSettings = {{
    {"cpSpaceSetIterations", 10, 1, 1000, true, {}, "",
     "the solver's passes per step; one damped spring's drag is done in the first"},
    // cpSpaceStep takes cpfpow(damping, dt): 0 would stop every body, above 1 adds energy.
    {"cpSpaceSetDamping", 1, 1e-6, 1, false, {}, "",
     "the fraction of every body's velocity kept per second (v *= damping^dt each step)"},
}};

Parameters parameters_of(double k, double c) {
  return {{"cpDampedSpringSetStiffness", k, "N/m"}, {"cpDampedSpringSetDamping", c, "N s/m"}};
}

// What Chipmunk does with (k, c): empty for a stiffness that is no spring (k <= 0) or a value that is not a
// finite number.
std::optional<Prediction> predict_spring(double m, double k, double c, double h, double damping) {
  if (!(k > 0.0) || !std::isfinite(k) || !std::isfinite(c)) return std::nullopt;
  return predict_from_step_map(chipmunk_step_map(m, k, c, h, damping), h);
}

bool meets(const Prediction& p, const Target& t) { return p.stable && meets_response(p, t.omega, t.damping_ratio); }

EngineReport report(const Target& t, const SettingValues& values) {
  EngineReport out;
  out.settings = describe_settings(kChipmunkModel, values);
  const double m = t.effective_mass, h = t.dt, damping = values[kChipmunkDamping];
  const double k = t.spring.stiffness, c = t.spring.damping;

  // The plain export: softtune's k, c are the spring's own fields.
  report_lines::plain_export(out, predict_spring(m, k, c, h, damping), parameters_of(k, c), kChipmunkModel.name, k,
                             "a cpDampedSpring needs a stiffness above 0");

  if (!(t.omega > 0.0)) return out;
  // Exact, in closed form: k = exact softness's k', c from det = d e = P.
  const ExactSpring closed = exact_spring(m, t.omega, t.damping_ratio, h);
  const double exact_c = 2.0 * t.damping_ratio * closed.omega * m + m * std::log(damping);
  std::optional<Prediction> p;
  if (closed.finite) p = predict_spring(m, closed.spring.stiffness, exact_c, h, damping);
  if (p && meets(*p, t)) {
    out.exact = parameters_of(closed.spring.stiffness, exact_c);
    out.exact_predicted = *p;
    return out;
  }
  report_lines::inexact(out, p, t, kChipmunkModel.name,
                        closed.clamped_to_nyquist ? "the asked frequency is above the step's Nyquist limit"
                                                  : "the poles are too fast for the step to represent");
  return out;
}

}  // namespace

// cpSpaceStep for one body on one cpDampedSpring (see the top of this file):
//   x1 = x + h v,  v1 = e d (v - h (k / m) x1),  d = damping^h,  e = exp(-c h / m)
Eigen::Matrix2d chipmunk_step_map(double m, double k, double c, double dt, double space_damping) {
  const double kept = std::pow(space_damping, dt) * std::exp(-c * dt / m);
  const double w2 = k / m;
  Eigen::Matrix2d a;
  a(0, 0) = 1.0;
  a(0, 1) = dt;
  a(1, 0) = -kept * dt * w2;
  a(1, 1) = kept * (1.0 - dt * dt * w2);
  return a;
}

const EngineModel kChipmunkModel = {
    "chipmunk",
    "Chipmunk 7.0.3: cpSpaceStep.c cpSpaceStep, cpBody.c cpBodyUpdatePosition and cpBodyUpdateVelocity, "
    "cpDampedSpring.c preStep and applyImpulse, cpSpace.c cpSpaceInit defaults",
    kSettings,
    report,
};

}  // namespace softtune::engines
