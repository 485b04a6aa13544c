#pragma once
// Discrete analysis of one integrator step [x1 v1]^T = A [x0 v0]^T: eigenvalues z of A, spectral radius,
// stability, largest stable step, steps per period, and the frequency and damping ratio the discrete
// motion actually has, read from s = ln(z) / h (docs/math.md, "Discrete analysis").

#include <Eigen/Core>
#include <complex>
#include <optional>

#include "softtune/methods.h"

namespace softtune {

/// Spectral radii within this distance of 1 are "marginal": bounded in exact arithmetic (e.g. semi-implicit
/// Euler undamped) but indistinguishable from slow growth in floating point. Documented in docs/math.md.
inline constexpr double kMarginalBand = 1e-9;

enum class Verdict { stable, marginal, unstable };

struct DiscreteAnalysis {
  Eigen::Matrix2d step_matrix;           ///< A, maps (x0, v0) to (x1, v1)
  std::complex<double> z1, z2;           ///< eigenvalues of A
  double spectral_radius = 0.0;          ///< max |z|
  Verdict verdict = Verdict::stable;
  std::optional<double> max_stable_h;    ///< s; empty = stable for every h
  std::optional<double> steps_per_period;  ///< 2 pi / (omega h) of the requested omega; empty when omega = 0
  std::optional<double> achieved_frequency_hz;  ///< |s| / (2 pi); empty when undefined (z = 0, saddle)
  std::optional<double> achieved_damping_ratio;  ///< -Re(s) / |s|
  /// Im(s) / (2 pi): the frequency of the visible oscillation, omega sqrt(1 - zeta^2) / (2 pi); 0 when the
  /// poles are real and positive (no oscillation).
  std::optional<double> achieved_damped_frequency_hz;
};

/// The step matrix, built by stepping the unit states (1, 0) and (0, 1): every method is linear.
Eigen::Matrix2d step_matrix(Method m, const StepModel& model);

/// Eigenvalues of a real 2x2 matrix.
void eigenvalues_2x2(const Eigen::Matrix2d& a, std::complex<double>& z1, std::complex<double>& z2);

/// Natural frequency (Hz) and damping ratio of the continuous system whose poles map to z1, z2 over h:
/// s = ln(z) / h. A complex pair gives omega = |s|, zeta = -Re(s)/|s|. Two positive real z give
/// omega^2 = s1 s2, zeta = -(s1 + s2) / (2 omega). A negative real z is an oscillation at Nyquist,
/// s = ln|z| / h + i pi / h. Returns false when undefined (a zero pole, or poles on both sides of 1).
bool achieved_from_poles(std::complex<double> z1, std::complex<double> z2, double h, double& frequency_hz,
                         double& damping_ratio);

/// The discrete poles of a fitted second-order recurrence and what they read as.
struct RecurrencePoles {
  std::complex<double> z1, z2;
  std::optional<double> frequency_hz;   ///< empty when achieved_from_poles is undefined
  std::optional<double> damping_ratio;
};

/// Poles of x[n] = p x[n-1] + q x[n-2] (+ b): the roots of z^2 - p z - q, i.e. the eigenvalues of the
/// companion matrix [[p, q], [1, 0]], read over the sample interval h. The one reading every fit shares
/// (response_fit, trajectory_fit, identify).
RecurrencePoles poles_of_recurrence(double p, double q, double h);

/// Largest stable h (s) in closed form from the Jury conditions on A (x = omega h):
///   explicit Euler:      x < 2 zeta for zeta <= 1, x < 2 (zeta - sqrt(zeta^2 - 1)) for zeta > 1
///                        (zeta = 0: never stable, returns 0)
///   semi-implicit Euler: x < 2 (sqrt(zeta^2 + 1) - zeta)    (zeta = 0: omega h < 2, the talk's limit)
///   implicit Euler, soft, soft_exact: every h (empty).
/// For soft_exact at zeta = 0 the symplectic spring with k' has omega' h = 2 sin(omega h / 2) < 2: every h.
std::optional<double> max_stable_step(Method m, double omega, double zeta);

/// The full analysis of a method; omega, zeta are the requested ones (for steps per period and h_max).
DiscreteAnalysis analyze(Method m, const StepModel& model, double omega, double zeta);

/// Classify a spectral radius: > 1 + kMarginalBand unstable, within the band marginal, else stable.
Verdict classify_spectral_radius(double spectral_radius);

}  // namespace softtune
