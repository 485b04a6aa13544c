#pragma once
// Reading the discrete poles back from a sampled trajectory (Prony's method), without the step matrix.
// Any linear two-state method gives positions that obey x[n+2] = p x[n+1] + q x[n] exactly
// (Cayley-Hamilton on its 2x2 step matrix A: p = trace A, q = -det A), also when sampled every n steps
// (A^n is 2x2 too). A least-squares fit of (p, q) over the samples gives the poles z^2 - p z - q = 0.

#include <complex>
#include <optional>
#include <span>

namespace softtune {

struct TrajectoryFit {
  std::complex<double> z1, z2;   ///< poles per sample interval
  double spectral_radius = 0.0;  ///< max |z| per sample interval
  std::optional<double> frequency_hz;   ///< natural frequency of s = ln(z) / dt; empty when undefined
  std::optional<double> damping_ratio;  ///< empty when undefined
};

/// Fits the poles of samples spaced dt (s). A trajectory with one visible mode (x[n+1] = z x[n], e.g. an
/// over-damped motion whose fast mode died in the first step) gets z1 = z, z2 = 0 and no frequency.
/// Empty when fewer than 4 samples, any sample is not finite, or all samples are zero.
std::optional<TrajectoryFit> fit_trajectory_poles(std::span<const double> x, double dt);

}  // namespace softtune
