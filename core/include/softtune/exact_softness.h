#pragma once
// "Exact" softness: spring constants k', c' whose soft constraint (== implicit Euler) has the discrete
// poles of the continuous oscillator, z = exp(s h) (docs/math.md, "Exact softness").
//
// Implicit Euler on m x'' + c' x' + k' x = 0 has the characteristic polynomial
//   (m + c'h + k'h^2) z^2 - (2m + c'h) z + m = 0.
// With P = z1 z2 = exp(-2 zeta omega h) and S = z1 + z2 matching it term by term gives
//   c' = m (S/P - 2) / h,   k' = m (1 + P - S) / (P h^2),   c' + h k' = m (1 - P) / (P h).
// To keep full precision when omega h is small, the code uses 1 + P - S = (1 - z1)(1 - z2) and
// S - 2P = z1 (1 - z2) + z2 (1 - z1), so that c' = m (S - 2P) / (P h), k' = m (1 - z1)(1 - z2) / (P h^2).
// Under-damped: z = e exp(+-i theta), e = exp(-zeta omega h), theta = omega_d h = omega sqrt(1 - zeta^2) h,
//   (1 - z1)(1 - z2) = (1 - e)^2 + 2 e (1 - cos theta),  S - 2P = 2 e ((1 - e) - (1 - cos theta)).
// Over-damped: z1,2 = exp(s1,2 h), s1,2 = -omega (zeta -+ sqrt(zeta^2 - 1)), both real.
// Poles can be matched only below Nyquist, omega_d h < pi (docs/math.md, "Exact softness"); above it omega is clamped to
// omega_d h = (1 - kNyquistMargin) pi. At omega_d h = pi itself the two poles merge into a double pole
// z = -exp(-zeta omega h); for zeta = 0 that is a Jordan block at -1 and the motion grows linearly
// without bound (found by the stability sweep, stability_sweep.h).

#include "softtune/softness.h"

namespace softtune {

struct ExactSpring {
  SpringConstants spring;         ///< k' (N/m) and c' (N s/m); c' may be negative
  Softness softness;              ///< gamma', beta' (unrepresentable when zeta = 0)
  double omega = 0.0;             ///< rad/s actually matched (clamped when above Nyquist)
  bool clamped_to_nyquist = false;
  /// False when k', c' overflow a double (a pole so fast it maps to z = 0, e.g. zeta omega h > ~350):
  /// the caller falls back to standard softness and says so.
  bool finite = true;
};

/// Fraction of Nyquist kept free by the clamp: the clamped poles stay a distinct pair.
inline constexpr double kNyquistMargin = 0.01;

/// Highest natural angular frequency (rad/s) whose poles a step h represents for a damping ratio:
/// omega_d h = (1 - kNyquistMargin) pi, so omega = (1 - kNyquistMargin) pi / (h sqrt(1 - zeta^2));
/// unbounded (infinity) for zeta >= 1.
double exact_max_omega(double damping_ratio, double h);

/// k', c' and the softness for mass m (kg), omega (rad/s), zeta, time step h (s).
ExactSpring exact_spring(double mass, double omega, double damping_ratio, double h);

}  // namespace softtune
