#include "softtune/softness.h"

#include <cmath>
#include <limits>

namespace softtune {

SpringConstants spring_constants(double mass, double omega, double damping_ratio) {
  return {mass * omega * omega, 2.0 * mass * damping_ratio * omega};
}

double natural_angular_frequency(const Oscillator& o) {
  return o.stiffness > 0.0 ? std::sqrt(o.stiffness / o.mass) : 0.0;
}

double damping_ratio_of(const Oscillator& o) {
  const double omega = natural_angular_frequency(o);
  return omega > 0.0 ? o.damping / (2.0 * o.mass * omega) : 0.0;
}

Softness softness_from_spring(double stiffness, double damping, double h) {
  if (std::isinf(stiffness) && stiffness > 0.0) return {0.0, 1.0, SoftnessKind::rigid};
  if (stiffness == 0.0 && damping == 0.0) return {0.0, 0.0, SoftnessKind::no_constraint};
  const double denominator = damping + h * stiffness;
  if (!(denominator > 0.0)) return {0.0, 0.0, SoftnessKind::unrepresentable};
  const double gamma = 1.0 / denominator;
  // 1/denominator overflows only for denominators below ~1e-308: say so instead of returning inf.
  if (std::isinf(gamma)) return {0.0, 0.0, SoftnessKind::unrepresentable};
  return {gamma, h * stiffness * gamma, SoftnessKind::soft};
}

SpringConstants spring_from_softness(double gamma, double beta, double h) {
  return {beta / (h * gamma), (1.0 - beta) / gamma};
}

double impulse_gamma(double gamma, double h) { return gamma / h; }

double bias_factor(double beta, double h) { return beta / h; }

SoftV3 soft_v3(double omega, double damping_ratio, double h) {
  if (omega == 0.0) return {0.0, 1.0, 0.0};
  const double a1 = 2.0 * damping_ratio + h * omega;
  const double a2 = h * omega * a1;
  const double a3 = 1.0 / (1.0 + a2);
  return {omega / a1, a2 * a3, a3};
}

}  // namespace softtune
