#include "softtune/stability_sweep.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace softtune {

SweepSettings default_sweep_settings() {
  SweepSettings s;
  s.frequency_ratios = {0.001, 0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.3, 0.5, 0.7, 1.0, 1.5, 2.0};
  s.stiffnesses = {2.0, 2e3, 2e6, 2e9, 1e12};
  s.damping_ratios = {0.0, 1e-3, 0.1, 0.5, 1.0, 10.0, 1000.0};
  s.masses = {1e-6, 1e-3, 1.0, 1e3, 1e6};
  s.steps = {1e-6, 1e-4, 1e-3, 1.0 / 60.0, 0.1};
  return s;
}

// A decaying run would sink into subnormal numbers, where every operation costs ten times more (a
// damped case of 100 000 steps ran at 300-500 ns a step instead of 20-40) and the end states lose their
// digits. Every step method is linear and homogeneous in (x, v), so both columns are scaled up by the
// same power of two whenever they shrink below 2^-500 (exact in binary floating point) and the scale
// is taken out of rho(M) at the end; growth still overflows to a non-finite state as before.
constexpr int kRescaleExponent = 500;
constexpr int kRescaleEvery = 64;  ///< steps between magnitude checks

std::optional<double> observed_spectral_radius(Method m, const StepModel& model, int steps) {
  State a{1.0, 0.0}, b{0.0, 1.0};
  const double tiny = std::ldexp(1.0, -kRescaleExponent);
  double log_scale = 0.0;  ///< ln of the factor the columns were multiplied by
  for (int i = 0; i < steps; ++i) {
    a = step(m, a, model);
    b = step(m, b, model);
    if (!std::isfinite(a.x) || !std::isfinite(a.v) || !std::isfinite(b.x) || !std::isfinite(b.v)) {
      return std::nullopt;
    }
    if (i % kRescaleEvery == kRescaleEvery - 1) {
      const double largest = std::max({std::abs(a.x), std::abs(a.v), std::abs(b.x), std::abs(b.v)});
      if (largest > 0.0 && largest < tiny) {
        for (double* v : {&a.x, &a.v, &b.x, &b.v}) *v = std::ldexp(*v, kRescaleExponent);
        log_scale += kRescaleExponent * std::numbers::ln2;
      }
    }
  }
  Eigen::Matrix2d map;
  map << a.x, b.x, a.v, b.v;
  std::complex<double> z1, z2;
  eigenvalues_2x2(map, z1, z2);
  const double rho_n = std::max(std::abs(z1), std::abs(z2));
  if (!std::isfinite(rho_n)) return std::nullopt;
  if (rho_n == 0.0) return 0.0;
  return std::exp((std::log(rho_n) - log_scale) / steps);
}

SweepCase run_sweep_case(SweepCase c, int observe_steps) {
  const double omega = std::sqrt(c.stiffness / c.mass);
  const StepModel model = make_step_model(c.mass, omega, c.damping_ratio, c.h);
  const DiscreteAnalysis a = analyze(c.method, model, omega, c.damping_ratio);
  c.spectral_radius = a.spectral_radius;
  c.predicted = a.verdict;
  c.observed_spectral_radius = observed_spectral_radius(c.method, model, observe_steps);
  c.observed = c.observed_spectral_radius ? classify_spectral_radius(*c.observed_spectral_radius) : Verdict::unstable;

  const double damped = c.damping_ratio < 1.0 ? c.frequency_ratio * std::sqrt(1.0 - c.damping_ratio * c.damping_ratio) : 0.0;
  if (damped > 0.5) c.warnings |= kBeyondNyquist;
  if (c.frequency_ratio > 0.25) c.warnings |= kFewStepsPerPeriod;
  if (c.method == Method::soft_exact && model.exact.clamped_to_nyquist) c.warnings |= kExactClampedToNyquist;
  if (c.method == Method::soft_exact && !model.exact.finite) c.warnings |= kExactOverflowFallback;
  if (c.observed != c.predicted) c.warnings |= kMismatch;
  return c;
}

namespace {

void count(SweepSummary& s, const SweepCase& c) {
  ++s.cases;
  if (c.predicted == Verdict::stable) ++s.predicted_stable;
  if (c.predicted == Verdict::marginal) ++s.predicted_marginal;
  if (c.predicted == Verdict::unstable) ++s.predicted_unstable;
  if (c.observed == Verdict::unstable) ++s.observed_unstable;
  if (c.observed != c.predicted) ++s.mismatches;
  const bool soft = c.method == Method::soft || c.method == Method::soft_exact;
  if (soft && c.observed == Verdict::unstable) ++s.soft_blowups;
  const double values[] = {c.frequency_ratio, c.damping_ratio, c.mass, c.stiffness, c.h, c.spectral_radius};
  bool finite = true;
  for (double v : values) finite = finite && std::isfinite(v);
  if (!finite) ++s.non_finite_values;
}

SweepCase make_case(SweepFamily family, double ratio, double zeta, double mass, double stiffness, double h) {
  SweepCase c;
  c.family = family;
  c.frequency_ratio = ratio;
  c.damping_ratio = zeta;
  c.mass = mass;
  c.stiffness = stiffness;
  c.h = h;
  return c;
}

}  // namespace

StepLimit find_step_limit(Method m, double zeta) {
  static const std::vector<double> scan = log_scan(kStepLimitLowest, kStepLimitHighest, kStepLimitScanPoints);
  const SpectralRadiusOf rho = [&](double omega_h) {
    std::complex<double> z1, z2;
    eigenvalues_2x2(step_matrix(m, make_step_model(1.0, omega_h, zeta, 1.0)), z1, z2);
    return std::max(std::abs(z1), std::abs(z2));
  };
  StepLimit out{m, zeta, find_stability_limit(rho, scan), std::nullopt};
  if (const auto h = max_stable_step(m, 1.0, zeta)) out.closed_form_omega_h = *h;
  return out;
}

namespace {

// k of a frequency-ratio case: k = m omega^2, omega = 2 pi (f h) / h; above max_stiffness it is skipped.
double frequency_case_stiffness(double ratio, double mass, double h) {
  const double omega = 2.0 * std::numbers::pi * ratio / h;
  return mass * omega * omega;
}

}  // namespace

std::size_t sweep_case_count(const SweepSettings& s) {
  std::size_t n = 0;
  for (double h : s.steps) {
    for (double mass : s.masses) {
      for (double ratio : s.frequency_ratios) n += frequency_case_stiffness(ratio, mass, h) <= s.max_stiffness ? 1 : 0;
    }
  }
  return (n + s.steps.size() * s.masses.size() * s.stiffnesses.size()) * s.damping_ratios.size() * s.methods.size();
}

SweepResult run_sweep(const SweepSettings& s, const SweepProgress& progress) {
  SweepResult out;
  bool go_on = true;
  for (Method m : s.methods) {
    for (double zeta : s.damping_ratios) {
      if (s.step_limits) out.step_limits.push_back(find_step_limit(m, zeta));
    }
  }
  const int n = std::max(1000, s.observe_steps);
  auto add = [&](SweepCase c) {
    for (Method m : s.methods) {
      if (!go_on) return;
      c.method = m;
      out.cases.push_back(run_sweep_case(c, n));
      count(out.summary, out.cases.back());
      if (progress) go_on = progress();
    }
  };
  for (double h : s.steps) {
    for (double mass : s.masses) {
      for (double zeta : s.damping_ratios) {
        for (double ratio : s.frequency_ratios) {
          const double k = frequency_case_stiffness(ratio, mass, h);
          if (k > s.max_stiffness) continue;
          add(make_case(SweepFamily::frequency_ratio, ratio, zeta, mass, k, h));
        }
        for (double k : s.stiffnesses) {
          const double ratio = std::sqrt(k / mass) * h / (2.0 * std::numbers::pi);
          add(make_case(SweepFamily::stiffness, ratio, zeta, mass, k, h));
        }
      }
    }
  }
  return out;
}

}  // namespace softtune
