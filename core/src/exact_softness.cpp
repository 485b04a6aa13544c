#include "softtune/exact_softness.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace softtune {

double exact_max_omega(double damping_ratio, double h) {
  if (damping_ratio >= 1.0) return std::numeric_limits<double>::infinity();
  return (1.0 - kNyquistMargin) * std::numbers::pi / (h * std::sqrt(1.0 - damping_ratio * damping_ratio));
}

namespace {

// (1 - z1)(1 - z2) and S - 2P for the continuous poles mapped by z = exp(s h) (see the header).
struct PoleTerms {
  double one_minus_product;  // (1 - z1)(1 - z2) = 1 + P - S
  double sum_minus_2p;       // S - 2P
  double product;            // P = z1 z2 = exp(-2 zeta omega h)
  double one_minus_p;        // 1 - P, without cancellation when P is near 1
};

PoleTerms pole_terms(double omega, double zeta, double h) {
  if (zeta <= 1.0) {
    const double e = std::exp(-zeta * omega * h);
    const double one_minus_e = -std::expm1(-zeta * omega * h);
    const double half_theta = 0.5 * omega * std::sqrt(1.0 - zeta * zeta) * h;
    const double sin_half = std::sin(half_theta);
    const double one_minus_cos = 2.0 * sin_half * sin_half;
    return {one_minus_e * one_minus_e + 2.0 * e * one_minus_cos, 2.0 * e * (one_minus_e - one_minus_cos), e * e,
            one_minus_e * (1.0 + e)};
  }
  const double root = std::sqrt(zeta * zeta - 1.0);
  const double s_slow = -omega / (zeta + root);  // = -omega (zeta - root) without cancellation
  const double s_fast = -omega * (zeta + root);
  const double z1 = std::exp(s_slow * h), z2 = std::exp(s_fast * h);
  const double d1 = -std::expm1(s_slow * h), d2 = -std::expm1(s_fast * h);
  return {d1 * d2, z1 * d2 + z2 * d1, z1 * z2, d1 + d2 - d1 * d2};
}

}  // namespace

ExactSpring exact_spring(double mass, double omega, double damping_ratio, double h) {
  ExactSpring out;
  const double max_omega = exact_max_omega(damping_ratio, h);
  out.clamped_to_nyquist = omega > max_omega;
  out.omega = out.clamped_to_nyquist ? max_omega : omega;
  if (out.omega == 0.0) {
    out.softness = softness_from_spring(0.0, 0.0, h);
    return out;
  }
  const PoleTerms t = pole_terms(out.omega, damping_ratio, h);
  const double P = t.product;
  out.spring.stiffness = mass * t.one_minus_product / (P * h * h);
  out.spring.damping = mass * t.sum_minus_2p / (P * h);
  if (!std::isfinite(out.spring.stiffness) || !std::isfinite(out.spring.damping)) {
    out.finite = false;
    out.spring = {};
    out.softness = {0.0, 0.0, SoftnessKind::unrepresentable};
    return out;
  }
  if (damping_ratio == 0.0) {
    // c' + h k' = 0 exactly: a symplectic spring with corrected stiffness; gamma is unbounded.
    out.spring.damping = -h * out.spring.stiffness;
    out.softness = {0.0, 0.0, SoftnessKind::unrepresentable};
    return out;
  }
  // c' + h k' = m (1 - P) / (P h).
  const double denominator = mass * t.one_minus_p / (P * h);
  const double gamma = 1.0 / denominator;
  if (!(denominator > 0.0) || std::isinf(gamma)) {
    out.softness = {0.0, 0.0, SoftnessKind::unrepresentable};
  } else {
    out.softness = {gamma, h * out.spring.stiffness * gamma, SoftnessKind::soft};
  }
  return out;
}

}  // namespace softtune
