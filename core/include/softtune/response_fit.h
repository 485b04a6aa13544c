#pragma once
// Measuring the response a simulation achieved: natural frequency and damping ratio fitted to a sampled
// trajectory, plus overshoot and settle time. Pure math on a vector of samples; no I/O.
//
// Method: Prony's method of order 2 with a constant term (linear prediction). A linear second-order
// system sampled every h seconds obeys, exactly, the recurrence
//   x[n] = a1 x[n-1] + a2 x[n-2] + b,
// whose characteristic roots z1, z2 (z^2 - a1 z - a2 = 0) are its discrete poles z = exp(s h); the constant b
// carries a non-zero equilibrium x_e = b / (1 - a1 - a2) (gravity sag, a rest length). a1, a2, b come from a
// linear least-squares fit over the window; s = ln(z) / h then gives omega = |s|, zeta = -Re(s) / |s|
// (achieved_from_poles in discrete_analysis.h, the same reading the step-matrix analysis uses). Unlike a
// log decrement it needs no peak picking, works for over-damped motion (two real poles) and is exact, not
// approximate, for the discrete trajectory of a soft constraint (which *is* such a recurrence).

#include <complex>
#include <optional>
#include <vector>

namespace softtune {

/// Settle band: the response has settled once it stays within this fraction of its initial deviation
/// from equilibrium (the usual 2 % criterion).
inline constexpr double kSettleBand = 0.02;

/// Samples whose distance from the final value is below this fraction of the largest distance are left out
/// of the fit: once the motion has decayed into round-off, they carry no information about the poles.
inline constexpr double kFitFloor = 1e-3;

struct ResponseFit {
  std::optional<double> frequency_hz;   ///< Hz, natural frequency |s| / (2 pi); empty when the fit fails
  std::optional<double> damping_ratio;  ///< -Re(s) / |s|
  std::optional<double> equilibrium;    ///< the value the motion decays to (fit, or the last sample)
  std::optional<double> overshoot;      ///< fraction of the initial deviation swung past equilibrium
  std::optional<int> settle_samples;    ///< first sample after which it stays in the settle band; empty: never
  std::optional<double> residual;       ///< RMS fit residual / RMS deviation of the window (0 = exact)
  int samples_used = 0;                 ///< samples that entered the least-squares fit
  std::optional<std::complex<double>> z1, z2;  ///< the fitted discrete poles per sample interval h
};

/// The number of leading samples worth fitting: up to the last one further than kFitFloor of the largest
/// distance from the final value (plus two, so the recurrence sees the tail start).
int fit_window(const std::vector<double>& samples);

/// Fits `samples`, spaced `h` seconds apart (h > 0). Needs at least 8 samples and some motion; otherwise
/// every field that cannot be computed is empty.
ResponseFit fit_response(const std::vector<double>& samples, double h);

/// Overshoot of a step response from x0 towards x_e: max(0, max_n -(x[n] - x_e) sign(x0 - x_e)) / |x0 - x_e|.
/// Continuous reference for an under-damped oscillator released from rest: exp(-pi zeta / sqrt(1 - zeta^2)).
std::optional<double> overshoot_of(const std::vector<double>& samples, double equilibrium);

/// Index of the first sample after which |x[n] - x_e| <= band |x[0] - x_e| holds to the end; empty when the
/// last sample is still outside the band or there is no initial deviation.
std::optional<int> settle_index(const std::vector<double>& samples, double equilibrium, double band);

}  // namespace softtune
