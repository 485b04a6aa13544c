#pragma once
// Spring constants and softness (docs/math.md; Catto GDC 2011, "2:3:2" and "3:3:2").
//
// The soft constraint J v2 + (beta/h) C + gamma lambda = 0, solved with semi-implicit Euler, is
// identical to implicit Euler on m x'' + c x' + k x = 0 when
//   gamma = 1 / (c + h k),  beta = h k / (c + h k)        (force form)
// The solver sees the impulse form: gamma_impulse = gamma / h, bias velocity = (beta / h) C.

namespace softtune {

/// A mass-spring-damper m x'' + c x' + k x = 0.
struct Oscillator {
  double mass = 1.0;       ///< kg (effective mass seen by the constraint)
  double stiffness = 0.0;  ///< k, N/m
  double damping = 0.0;    ///< c, N s/m (may be negative in exact mode)
};

/// Spring constants for a mass: k = m omega^2, c = 2 m zeta omega (Catto GDC 2011, "3:3:2").
struct SpringConstants {
  double stiffness = 0.0;  ///< k, N/m
  double damping = 0.0;    ///< c, N s/m
};
SpringConstants spring_constants(double mass, double omega, double damping_ratio);

/// Natural angular frequency in rad/s: omega = sqrt(k / m).
double natural_angular_frequency(const Oscillator& o);

/// Damping ratio: zeta = c / (2 m omega); 0 when omega is 0.
double damping_ratio_of(const Oscillator& o);

/// What a (k, c, h) triple means for the solver.
enum class SoftnessKind {
  soft,             ///< 0 < gamma < infinity
  rigid,            ///< k -> infinity: gamma = 0, beta = 1
  no_constraint,    ///< k = c = 0: the constraint does nothing (gamma unbounded)
  unrepresentable,  ///< c + h k <= 0 with k or c non-zero: gamma unbounded or negative
};

/// Force-form softness. gamma and beta are meaningful only for `soft` and `rigid`.
struct Softness {
  double gamma = 0.0;  ///< CFM, force form, m/(N s) for a linear constraint
  double beta = 0.0;   ///< ERP, dimensionless in [0, 1] for k, c >= 0
  SoftnessKind kind = SoftnessKind::soft;
};

/// gamma = 1 / (c + h k), beta = h k / (c + h k) (Catto GDC 2011, "2:3:2").
/// k = +infinity gives the rigid limit; k = c = 0 gives no_constraint; never divides by zero.
Softness softness_from_spring(double stiffness, double damping, double h);

/// Inverse (Catto GDC 2011, "2:3:2"): k = beta / (h gamma), c = (1 - beta) / gamma. Needs gamma > 0.
SpringConstants spring_from_softness(double gamma, double beta, double h);

/// Impulse form of gamma (what Box2D 2.4 stores as m_gamma): gamma_impulse = gamma / h.
double impulse_gamma(double gamma, double h);

/// Bias velocity factor: bias velocity = (beta / h) C.
double bias_factor(double beta, double h);

/// Box2D v3's soft parameters (b2MakeSoft in box2d/src/solver.h):
///   a1 = 2 zeta + h omega, a2 = h omega a1, a3 = 1 / (1 + a2)
///   bias_rate = omega / a1, mass_scale = a2 a3, impulse_scale = a3.
/// omega = 0 gives {0, 1, 0} as b2MakeSoft does for hertz = 0 (a rigid constraint in v3).
struct SoftV3 {
  double bias_rate = 0.0;      ///< 1/s
  double mass_scale = 1.0;     ///< dimensionless
  double impulse_scale = 0.0;  ///< dimensionless
};
SoftV3 soft_v3(double omega, double damping_ratio, double h);

}  // namespace softtune
