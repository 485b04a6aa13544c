#include "softtune/discrete_analysis.h"

#include <cmath>
#include <numbers>

namespace softtune {
namespace {

// |z| without std::abs(complex), which goes through hypot; falls back to it only on overflow.
double modulus(std::complex<double> z) {
  const double r = std::sqrt(z.real() * z.real() + z.imag() * z.imag());
  return std::isfinite(r) ? r : std::hypot(z.real(), z.imag());
}

// ln z = ln|z| + i arg z; glibc's precise clog sorts terms (qsort) and costs ~10x this.
std::complex<double> log_of(std::complex<double> z) { return {std::log(modulus(z)), std::atan2(z.imag(), z.real())}; }

}  // namespace

Eigen::Matrix2d step_matrix(Method m, const StepModel& model) {
  const State col_x = step(m, {1.0, 0.0}, model);
  const State col_v = step(m, {0.0, 1.0}, model);
  Eigen::Matrix2d a;
  a << col_x.x, col_v.x, col_x.v, col_v.v;
  return a;
}

void eigenvalues_2x2(const Eigen::Matrix2d& a, std::complex<double>& z1, std::complex<double>& z2) {
  const double half_trace = 0.5 * (a(0, 0) + a(1, 1));
  const double det = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  // Discriminant as ((a - d)/2)^2 + b c: avoids cancellation of trace^2/4 - det for close eigenvalues.
  const double half_diff = 0.5 * (a(0, 0) - a(1, 1));
  const double disc = half_diff * half_diff + a(0, 1) * a(1, 0);
  if (disc < 0.0) {
    const double im = std::sqrt(-disc);
    z1 = {half_trace, im};
    z2 = {half_trace, -im};
    return;
  }
  // Real: the larger-magnitude root directly, the other from det / z1 (no cancellation).
  const double root = std::sqrt(disc);
  const double big = half_trace >= 0.0 ? half_trace + root : half_trace - root;
  z1 = big;
  z2 = big != 0.0 ? det / big : half_trace - (half_trace >= 0.0 ? root : -root);
}

RecurrencePoles poles_of_recurrence(double p, double q, double h) {
  Eigen::Matrix2d companion;
  companion << p, q, 1.0, 0.0;
  RecurrencePoles out;
  eigenvalues_2x2(companion, out.z1, out.z2);
  double f = 0.0, zeta = 0.0;
  if (achieved_from_poles(out.z1, out.z2, h, f, zeta)) {
    out.frequency_hz = f;
    out.damping_ratio = zeta;
  }
  return out;
}

bool achieved_from_poles(std::complex<double> z1, std::complex<double> z2, double h, double& frequency_hz,
                         double& damping_ratio) {
  const double r1 = modulus(z1), r2 = modulus(z2);
  if (!(r1 > 0.0) || !(r2 > 0.0) || !std::isfinite(r1) || !std::isfinite(r2)) return false;
  std::complex<double> s;
  if (z1.imag() != 0.0) {
    s = log_of(z1) / h;
  } else if (z1.real() > 0.0 && z2.real() > 0.0) {
    const double s1 = std::log(z1.real()) / h, s2 = std::log(z2.real()) / h;
    const double product = s1 * s2;
    if (!(product > 0.0)) return false;
    const double omega = std::sqrt(product);
    frequency_hz = omega / (2.0 * std::numbers::pi);
    damping_ratio = -(s1 + s2) / (2.0 * omega);
    return std::isfinite(frequency_hz) && std::isfinite(damping_ratio);
  } else {
    s = {std::log(std::sqrt(r1 * r2)) / h, std::numbers::pi / h};
  }
  const double omega = modulus(s);
  if (!(omega > 0.0) || !std::isfinite(omega)) return false;
  frequency_hz = omega / (2.0 * std::numbers::pi);
  // An undamped pole has s.real() == +0, and -(+0) is -0: reports would print "-0".
  damping_ratio = s.real() == 0.0 ? 0.0 : -s.real() / omega;
  return true;
}

std::optional<double> max_stable_step(Method m, double omega, double zeta) {
  if (omega <= 0.0) return std::nullopt;
  switch (m) {
    case Method::explicit_euler:
      return (zeta <= 1.0 ? 2.0 * zeta : 2.0 * (zeta - std::sqrt(zeta * zeta - 1.0))) / omega;
    case Method::semi_implicit_euler:
      return 2.0 * (std::sqrt(zeta * zeta + 1.0) - zeta) / omega;
    case Method::implicit_euler:
    case Method::soft:
    case Method::soft_exact:
      return std::nullopt;
  }
  return std::nullopt;
}

Verdict classify_spectral_radius(double spectral_radius) {
  if (!(spectral_radius <= 1.0 + kMarginalBand)) return Verdict::unstable;  // also catches NaN
  if (spectral_radius >= 1.0 - kMarginalBand) return Verdict::marginal;
  return Verdict::stable;
}

DiscreteAnalysis analyze(Method m, const StepModel& model, double omega, double zeta) {
  DiscreteAnalysis out;
  out.step_matrix = step_matrix(m, model);
  eigenvalues_2x2(out.step_matrix, out.z1, out.z2);
  out.spectral_radius = std::max(modulus(out.z1), modulus(out.z2));
  out.verdict = classify_spectral_radius(out.spectral_radius);
  out.max_stable_h = max_stable_step(m, omega, zeta);
  if (omega > 0.0) out.steps_per_period = 2.0 * std::numbers::pi / (omega * model.h);
  double f = 0.0, z = 0.0;
  if (achieved_from_poles(out.z1, out.z2, model.h, f, z)) {
    out.achieved_frequency_hz = f;
    out.achieved_damping_ratio = z;
    out.achieved_damped_frequency_hz = z < 1.0 ? f * std::sqrt(1.0 - z * z) : 0.0;
  }
  return out;
}

}  // namespace softtune
