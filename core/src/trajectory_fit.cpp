#include "softtune/trajectory_fit.h"

#include <algorithm>
#include <cmath>

#include "softtune/discrete_analysis.h"

namespace softtune {
namespace {

// Columns this close to collinear (normal matrix determinant relative to its diagonal product) hold
// one mode only: a 2-pole fit would be noise.
constexpr double kCollinear = 1e-10;

}  // namespace

std::optional<TrajectoryFit> fit_trajectory_poles(std::span<const double> x, double dt) {
  if (x.size() < 4) return std::nullopt;
  double scale = 0.0;
  for (double v : x) {
    if (!std::isfinite(v)) return std::nullopt;
    scale = std::max(scale, std::abs(v));
  }
  if (scale == 0.0) return std::nullopt;
  // Normal equations of min sum (x[n+2] - p x[n+1] - q x[n])^2, on samples scaled to max 1.
  double s11 = 0, s10 = 0, s00 = 0, r1 = 0, r0 = 0;
  for (std::size_t n = 0; n + 2 < x.size(); ++n) {
    const double a = x[n + 1] / scale, b = x[n] / scale, y = x[n + 2] / scale;
    s11 += a * a;
    s10 += a * b;
    s00 += b * b;
    r1 += a * y;
    r0 += b * y;
  }
  TrajectoryFit fit;
  const double det = s11 * s00 - s10 * s10;
  if (!(std::abs(det) > kCollinear * s11 * s00)) {
    // One mode: x[n+1] = z x[n].
    double num = 0, den = 0;
    for (std::size_t n = 0; n + 1 < x.size(); ++n) {
      num += x[n + 1] / scale * (x[n] / scale);
      den += x[n] / scale * (x[n] / scale);
    }
    if (!(den > 0.0)) return std::nullopt;
    fit.z1 = num / den;
    fit.z2 = 0.0;
    fit.spectral_radius = std::abs(fit.z1);
    return fit;
  }
  const double p = (r1 * s00 - r0 * s10) / det;
  const double q = (s11 * r0 - s10 * r1) / det;
  const RecurrencePoles poles = poles_of_recurrence(p, q, dt);
  fit.z1 = poles.z1;
  fit.z2 = poles.z2;
  fit.spectral_radius = std::max(std::abs(fit.z1), std::abs(fit.z2));
  fit.frequency_hz = poles.frequency_hz;
  fit.damping_ratio = poles.damping_ratio;
  return fit;
}

}  // namespace softtune
