#pragma once
// The step Jolt and Rapier share (each model cites its own engine lines): a soft constraint in Erin Catto's
// impulse form -- softness 1 / (h (c + h k)), bias h k softness C, soft mass 1 / (1/m + softness) -- solved
// once per substep of length h, with the velocity scaled by `velocity_scale` before the solve (an engine's
// per-substep linear damping), then x += h v (symplectic Euler). With one constraint the first velocity
// iteration converges, and warm starting cancels (the total impulse solves J v + softness P + bias = 0
// whatever impulse was applied first), so the substep is implicit Euler on (m, k, c) after the scale:
//   (m + h c + h^2 k) v1 = m a v0 - h k x0,   x1 = x0 + h v1.
// Internal to core/src/engines (jolt.cpp, rapier.cpp).

#include <Eigen/Core>
#include <cmath>

#include "softtune/designer.h"
#include "softtune/engines/engine_model.h"
#include <numbers>
#include <optional>

namespace softtune::engines::soft_substeps {

/// The substep map on (x, v).
inline Eigen::Matrix2d substep_map(double m, double k, double c, double h, double velocity_scale) {
  const double d = m + h * c + h * h * k;
  Eigen::Matrix2d s;
  s(1, 0) = -h * k / d;
  s(1, 1) = m * velocity_scale / d;
  s(0, 0) = 1.0 + h * s(1, 0);
  s(0, 1) = h * s(1, 1);
  return s;
}

/// a^n for n >= 1 (square and multiply).
inline Eigen::Matrix2d power(Eigen::Matrix2d a, int n) {
  Eigen::Matrix2d out = Eigen::Matrix2d::Identity();
  while (n > 0) {
    if (n & 1) out = out * a;
    n >>= 1;
    if (n > 0) a = a * a;
  }
  return out;
}

struct Spring {
  double k = 0.0, c = 0.0;
};

/// The spring whose substep (velocity scale a) has the poles exp(s h) of the oscillator (omega, zeta):
/// softtune's exact spring (k', c', exact_softness.h) corrected for the scale. The substep's
/// characteristic polynomial is (m + h c + h^2 k) z^2 - (m (1 + a) + h c) z + m a, so matching
/// P = z1 z2 and S = z1 + z2 gives D = m a / P, h^2 k = m a + D (1 - S), h c = D - m - h^2 k; with k', c'
/// the a = 1 answer: k = a k', c = a c' - m (1 - a) / h.
inline Spring exact_scaled(double m, double k_exact, double c_exact, double h, double a) {
  return {a * k_exact, a * c_exact - m * (1.0 - a) / h};
}

/// What a spring built by exact_scaled does, without computing its eigenvalues: its poles are exp(s h) per
/// substep by construction (the model tests check this against the step map), so per step of dt they are
/// exp(s dt): the asked omega and zeta, spectral radius exp(-omega (zeta - sqrt(zeta^2 - 1)) dt) for
/// zeta > 1, else exp(-zeta omega dt).
inline Prediction matched_prediction(double omega, double zeta, double dt) {
  const double rate = zeta > 1.0 ? omega * (zeta - std::sqrt(zeta * zeta - 1.0)) : zeta * omega;
  return {frequency_from_angular(omega), zeta, std::exp(-rate * dt), true};
}

/// The least-damped spring the engine takes, c + h k = margin h k, whose substep poles have natural
/// frequency omega: D = m + margin h^2 k, P = m a / D, |z| = sqrt(P); the pole angle phi keeps
/// ln^2 |z| + phi^2 = (omega h)^2, S = 2 |z| cos phi, and k = m (1 + a - S) / (h^2 (1 + margin (S - 1)))
/// (from S D = D + m a - h^2 k). |z| barely moves with k, so a few fixed-point passes settle it. Empty when
/// no such spring exists (the poles would pass Nyquist, or the scale kills the velocity).
inline std::optional<Spring> least_damped(double m, double omega, double h, double a, double margin) {
  if (!(a > 0.0) || !(omega > 0.0)) return std::nullopt;
  double k = m * omega * omega;
  for (int pass = 0; pass < 4; ++pass) {
    const double p = m * a / (m + margin * h * h * k);
    const double log_r = 0.5 * std::log(p);
    const double phi2 = omega * omega * h * h - log_r * log_r;
    if (!(phi2 > 0.0) || phi2 >= 0.98 * 0.98 * std::numbers::pi * std::numbers::pi) return std::nullopt;
    const double s = 2.0 * std::sqrt(p) * std::cos(std::sqrt(phi2));
    k = m * (1.0 + a - s) / (h * h * (1.0 + margin * (s - 1.0)));
    if (!(k > 0.0) || !std::isfinite(k)) return std::nullopt;
  }
  return Spring{k, (margin - 1.0) * h * k};
}

}  // namespace softtune::engines::soft_substeps
