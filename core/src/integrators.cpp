#include "softtune/integrators.h"

namespace softtune {
namespace {
double acceleration(State s, const Oscillator& o) { return -(o.stiffness * s.x + o.damping * s.v) / o.mass; }
}  // namespace

State explicit_euler_step(State s, const Oscillator& o, double h) {
  return {s.x + h * s.v, s.v + h * acceleration(s, o)};
}

State semi_implicit_euler_step(State s, const Oscillator& o, double h) {
  const double v1 = s.v + h * acceleration(s, o);
  return {s.x + h * v1, v1};
}

State implicit_euler_step(State s, const Oscillator& o, double h) {
  const double v1 = (o.mass * s.v - h * o.stiffness * s.x) / (o.mass + h * o.damping + h * h * o.stiffness);
  return {s.x + h * v1, v1};
}

State soft_step(State s, double mass, const Softness& softness, double h) {
  if (softness.kind != SoftnessKind::soft && softness.kind != SoftnessKind::rigid) return {s.x + h * s.v, s.v};
  const double lambda = -(s.v + softness.beta * s.x / h) / (h / mass + softness.gamma);
  const double v1 = s.v + h * lambda / mass;
  return {s.x + h * v1, v1};
}

State soft_substep(State s, const Oscillator& o, double h, int substeps) {
  const double sub_h = h / substeps;
  const Softness softness = softness_from_spring(o.stiffness, o.damping, sub_h);
  for (int i = 0; i < substeps; ++i) s = soft_step(s, o.mass, softness, sub_h);
  return s;
}

}  // namespace softtune
