#include "softtune/methods.h"

namespace softtune {

std::string_view method_name(Method m) {
  switch (m) {
    case Method::explicit_euler: return "explicit_euler";
    case Method::semi_implicit_euler: return "semi_implicit_euler";
    case Method::implicit_euler: return "implicit_euler";
    case Method::soft: return "soft";
    case Method::soft_exact: return "soft_exact";
  }
  return "soft";
}

StepModel make_step_model(double mass, double omega, double zeta, double h) {
  StepModel model;
  model.h = h;
  const SpringConstants sc = spring_constants(mass, omega, zeta);
  model.spring = {mass, sc.stiffness, sc.damping};
  model.soft = softness_from_spring(sc.stiffness, sc.damping, h);
  model.exact = exact_spring(mass, omega, zeta, h);
  if (!model.exact.finite) {
    // k', c' overflow: fall back to the standard constants (the tune result warns about it).
    model.exact.spring = sc;
    model.exact.softness = model.soft;
  }
  return model;
}

Oscillator method_spring(Method m, const StepModel& model) {
  if (m != Method::soft_exact) return model.spring;
  return {model.spring.mass, model.exact.spring.stiffness, model.exact.spring.damping};
}

State step(Method m, State s, const StepModel& model) {
  switch (m) {
    case Method::explicit_euler: return explicit_euler_step(s, model.spring, model.h);
    case Method::semi_implicit_euler: return semi_implicit_euler_step(s, model.spring, model.h);
    case Method::implicit_euler: return implicit_euler_step(s, model.spring, model.h);
    case Method::soft: return soft_step(s, model.spring.mass, model.soft, model.h);
    case Method::soft_exact:
      if (model.exact.softness.kind == SoftnessKind::soft) {
        return soft_step(s, model.spring.mass, model.exact.softness, model.h);
      }
      // Implicit Euler with c' = -h k' is exactly semi-implicit Euler with k' and no damping.
      return semi_implicit_euler_step(s, {model.spring.mass, model.exact.spring.stiffness, 0.0}, model.h);
  }
  return s;
}

}  // namespace softtune
