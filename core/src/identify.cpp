#include "softtune/identify.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "softtune/discrete_analysis.h"
#include "softtune/response_fit.h"
#include "softtune/trajectory_fit.h"

namespace softtune {
namespace {

using Series = std::vector<std::vector<double>>;  // one vector per probe, all the same length

// Prony (fit_response) needs 8 samples; fewer leaves nothing to fit.
constexpr int kMinFitSamples = 8;
// Held frames are taken for engine steps only when the steps fit at least this much better (residual ratio).
constexpr double kHoldGain = 0.5;
// Repeated samples needed, as a fraction of the moving samples, before held frames are considered.
constexpr double kHoldFraction = 0.02;

void add_verdict(std::vector<IdentifyVerdict>& list, IdentifyVerdict v) {
  if (std::find(list.begin(), list.end(), v) == list.end()) list.push_back(v);
}

// Least-squares line t = a + b n through the timestamps.
struct Grid {
  double start = 0.0, interval = 0.0, deviation = 0.0;
};
Grid fit_grid(const std::vector<double>& t) {
  const double n = static_cast<double>(t.size());
  const double mean_i = (n - 1.0) / 2.0;
  double mean_t = 0.0;
  for (double v : t) mean_t += v;
  mean_t /= n;
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double di = static_cast<double>(i) - mean_i;
    sxy += di * (t[i] - mean_t);
    sxx += di * di;
  }
  Grid g;
  g.interval = sxy / sxx;
  g.start = mean_t - g.interval * mean_i;
  for (std::size_t i = 0; i < t.size(); ++i) {
    g.deviation = std::max(g.deviation, std::abs(t[i] - g.start - g.interval * static_cast<double>(i)));
  }
  g.deviation /= g.interval;
  return g;
}

// Linear interpolation of every probe onto t0 + i h: the median interval, capped so the grid stays within
// kIdentifyMaxSamples rows however unevenly the recording was sampled.
Series resample(const Recording& r, double& h) {
  std::vector<double> gaps(r.time_s.size() - 1);
  for (std::size_t i = 0; i + 1 < r.time_s.size(); ++i) gaps[i] = r.time_s[i + 1] - r.time_s[i];
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  const double span = r.time_s.back() - r.time_s.front();
  h = std::max(gaps[gaps.size() / 2], span / static_cast<double>(kIdentifyMaxSamples - 1));
  const std::size_t rows = static_cast<std::size_t>(std::floor(span / h + 1e-9)) + 1;
  Series out(r.probes.size(), std::vector<double>(rows));
  std::size_t j = 0;
  for (std::size_t i = 0; i < rows; ++i) {
    const double t = r.time_s.front() + h * static_cast<double>(i);
    while (j + 2 < r.time_s.size() && r.time_s[j + 1] < t) ++j;
    const double w = std::clamp((t - r.time_s[j]) / (r.time_s[j + 1] - r.time_s[j]), 0.0, 1.0);
    for (std::size_t k = 0; k < r.probes.size(); ++k) out[k][i] = r.probes[k][j] + w * (r.probes[k][j + 1] - r.probes[k][j]);
  }
  return out;
}

// The samples that carry motion: the longest fit_window over the probes.
int moving_samples(const Series& x) {
  int n = 0;
  for (const auto& probe : x) n = std::max(n, fit_window(probe));
  return n;
}

// Held frames: each run of rows in which no probe changes is one engine step. Returns the first row of
// every run (empty when too few rows repeat while the probes move to call it holding).
std::vector<std::size_t> held_steps(const Series& x) {
  const int moving = moving_samples(x);
  int repeats = 0;
  for (int n = 1; n < moving; ++n) {
    bool same = true;
    for (const auto& probe : x) same = same && probe[n] == probe[n - 1];
    repeats += same ? 1 : 0;
  }
  if (repeats < 2 || repeats < kHoldFraction * (moving - 1)) return {};
  std::vector<std::size_t> starts = {0};
  for (std::size_t n = 1; n < x.front().size(); ++n) {
    bool same = true;
    for (const auto& probe : x) same = same && probe[n] == probe[n - 1];
    if (!same) starts.push_back(n);
  }
  return starts;
}

// A plateau of kIdentifyClipRun or more equal samples at the probe's largest or smallest value that ends
// before the record does (a settled tail is not a clip).
bool clipped(const std::vector<double>& x) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  for (double level : {*lo, *hi}) {
    int run = 0;
    for (std::size_t n = 0; n < x.size(); ++n) {
      run = x[n] == level ? run + 1 : 0;
      if (run >= kIdentifyClipRun && n + 1 < x.size() && x[n + 1] != level) return true;
    }
  }
  return false;
}

// The variable-projection model at poles (p, q): columns 1, u, w over n samples, orthonormalised by
// modified Gram-Schmidt run twice ("twice is enough": orthogonal to round-off), so the projections below
// are exact to round-off and cost a few passes over the samples. Buffers are reused between calls.
struct Projection {
  Eigen::MatrixXd basis;         // n x 3: 1, u, w
  Eigen::MatrixXd q;             // n x 3, orthonormal, basis = q r
  Eigen::Matrix3d r;
  Eigen::MatrixXd coefficients;  // 3 x probes, in the basis (1, u, w)
  Eigen::MatrixXd residual;      // n x probes
  double cost = 0.0;             // sum of squared residuals (normalised units)
  bool ok = false;
};

void project(double p, double q, const Eigen::MatrixXd& y, Projection& out) {
  out.ok = false;
  const Eigen::Index n = y.rows();
  out.basis.resize(n, 3);
  out.q.resize(n, 3);
  double* one = out.basis.col(0).data();
  double* u = out.basis.col(1).data();
  double* w = out.basis.col(2).data();
  one[0] = one[1] = 1.0;
  u[0] = 1.0, u[1] = 0.0;
  w[0] = 0.0, w[1] = 1.0;
  for (Eigen::Index i = 2; i < n; ++i) {
    one[i] = 1.0;
    u[i] = p * u[i - 1] + q * u[i - 2];
    w[i] = p * w[i - 1] + q * w[i - 2];
  }
  if (!out.basis.allFinite() || out.basis.cwiseAbs().maxCoeff() > 1e150) return;
  out.r.setZero();
  for (int j = 0; j < 3; ++j) {
    out.q.col(j) = out.basis.col(j);
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i < j; ++i) {
        const double d = out.q.col(i).dot(out.q.col(j));
        out.r(i, j) += d;
        out.q.col(j) -= d * out.q.col(i);
      }
    }
    out.r(j, j) = out.q.col(j).norm();
    if (!(out.r(j, j) > 1e-12 * out.basis.col(j).norm())) return;  // (numerically) dependent columns
    out.q.col(j) /= out.r(j, j);
  }
  const Eigen::MatrixXd qty = out.q.transpose() * y;
  out.coefficients = out.r.triangularView<Eigen::Upper>().solve(qty);
  out.residual = y - out.q * qty;
  out.cost = out.residual.squaredNorm();
  out.ok = std::isfinite(out.cost);
}

// Levenberg-Marquardt on (p, q) with Kaufman's variable-projection Jacobian J = -(I - P) dPhi/dtheta c: for
// each probe, g_p[n+2] = p g_p[n+1] + q g_p[n] + h[n+1] and g_q[n+2] = p g_q[n+1] + q g_q[n] + h[n], where
// h = a u + w_b w is the probe's homogeneous motion (differentiate u[n+2] = p u[n+1] + q u[n]).
// Stops when a step gains less than kIdentifyStopGain of the cost, or after kIdentifyMaxIterations.
Projection refine(double& p, double& q, const Eigen::MatrixXd& y) {
  Projection best, trial;
  project(p, q, y, best);
  if (!best.ok) return best;
  double lambda = 1e-3;
  const Eigen::Index n = y.rows();
  Eigen::MatrixXd g(n, 2);
  Eigen::VectorXd h(n);
  for (int iter = 0; iter < kIdentifyMaxIterations; ++iter) {
    Eigen::Matrix2d jtj = Eigen::Matrix2d::Zero();
    Eigen::Vector2d jtr = Eigen::Vector2d::Zero();
    for (Eigen::Index k = 0; k < y.cols(); ++k) {
      h.noalias() = best.basis.rightCols<2>() * best.coefficients.col(k).tail<2>();
      g.row(0).setZero();
      g.row(1).setZero();
      for (Eigen::Index i = 2; i < n; ++i) {
        g(i, 0) = p * g(i - 1, 0) + q * g(i - 2, 0) + h(i - 1);
        g(i, 1) = p * g(i - 1, 1) + q * g(i - 2, 1) + h(i - 2);
      }
      const Eigen::Matrix<double, 3, 2> qtg = best.q.transpose() * g;
      g -= best.q * qtg;  // (I - P) dPhi/dtheta c; J is its negative
      jtj += g.transpose() * g;
      jtr -= g.transpose() * best.residual.col(k);
    }
    bool improved = false;
    while (lambda < 1e12) {
      Eigen::Matrix2d a = jtj;
      a.diagonal() += lambda * jtj.diagonal().cwiseMax(1e-300);
      const Eigen::Vector2d step = a.ldlt().solve(-jtr);
      if (!step.allFinite()) break;
      project(p + step(0), q + step(1), y, trial);
      if (trial.ok && trial.cost < best.cost) {
        const double gain = (best.cost - trial.cost) / std::max(best.cost, 1e-300);
        p += step(0);
        q += step(1);
        std::swap(best, trial);
        lambda = std::max(lambda / 3.0, 1e-12);
        improved = gain > kIdentifyStopGain;
        break;
      }
      lambda *= 4.0;
    }
    if (!improved) break;
  }
  return best;
}

// Starting poles: Prony with a constant term on the first probe that has them, else the one-mode fit of
// its deviation from the last sample (an over-damped creep), else none.
std::optional<std::pair<double, double>> initial_poles(const Series& x, double h) {
  for (const auto& probe : x) {
    const ResponseFit fit = fit_response(probe, h);
    if (fit.z1 && fit.z2) return std::pair{(*fit.z1 + *fit.z2).real(), -(*fit.z1 * *fit.z2).real()};
  }
  for (const auto& probe : x) {
    std::vector<double> d(probe.size());
    for (std::size_t i = 0; i < probe.size(); ++i) d[i] = probe[i] - probe.back();
    if (auto fit = fit_trajectory_poles(d, h)) return std::pair{(fit->z1 + fit->z2).real(), -(fit->z1 * fit->z2).real()};
  }
  return std::nullopt;
}

MotionFit fit_motion(const Series& x, double h) {
  MotionFit out;
  const int n = moving_samples(x);
  out.samples_used = n;
  if (n < static_cast<int>(kIdentifyMinSamples)) add_verdict(out.verdicts, IdentifyVerdict::too_short);
  for (const auto& probe : x) {
    if (clipped(probe)) add_verdict(out.verdicts, IdentifyVerdict::clipped);
  }
  // Each probe centred and scaled to unit largest deviation, so probes in different units weigh alike.
  Eigen::MatrixXd y(std::max(n, 0), static_cast<Eigen::Index>(x.size()));
  std::vector<double> mean(x.size(), 0.0), scale(x.size(), 0.0);
  for (std::size_t k = 0; k < x.size(); ++k) {
    for (int i = 0; i < n; ++i) mean[k] += x[k][i] / n;
    for (int i = 0; i < n; ++i) scale[k] = std::max(scale[k], std::abs(x[k][i] - mean[k]));
    for (int i = 0; i < n; ++i) y(i, static_cast<Eigen::Index>(k)) = scale[k] > 0.0 ? (x[k][i] - mean[k]) / scale[k] : 0.0;
  }
  const bool moves = std::any_of(scale.begin(), scale.end(), [](double s) { return s > 0.0; });
  const auto init = n >= kMinFitSamples && moves ? initial_poles(x, h) : std::nullopt;
  if (!init) {
    add_verdict(out.verdicts, IdentifyVerdict::not_oscillating);
    return out;
  }
  double p = init->first, q = init->second;
  // On a long record the cost is a narrow valley in (p, q) (the phase error grows with every sample), so
  // the poles are refined on growing leading windows first, each starting from the last: a few cheap
  // iterations on 256 samples take a biased Prony start most of the way.
  for (Eigen::Index m = kIdentifyWarmWindow; m < n / 2; m *= 4) {
    double pm = p, qm = q;
    const Eigen::MatrixXd head = y.topRows(m);
    if (refine(pm, qm, head).ok) p = pm, q = qm;
  }
  const Projection fit = refine(p, q, y);
  if (!fit.ok) {
    add_verdict(out.verdicts, IdentifyVerdict::not_oscillating);
    return out;
  }
  const RecurrencePoles poles = poles_of_recurrence(p, q, h);
  const std::complex<double> z1 = poles.z1, z2 = poles.z2;
  out.z1 = z1;
  out.z2 = z2;
  out.frequency_hz = poles.frequency_hz;
  out.damping_ratio = poles.damping_ratio;
  // Im(s) / 2 pi of the pole of largest modulus; a negative real pole oscillates at Nyquist.
  const std::complex<double> dominant = std::abs(z1) >= std::abs(z2) ? z1 : z2;
  const bool oscillates = std::abs(dominant.imag()) > 0.0 || dominant.real() < 0.0;
  out.damped_frequency_hz = oscillates ? std::abs(std::arg(dominant)) / (2.0 * std::numbers::pi * h) : 0.0;
  double motion = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double c0 = fit.coefficients(0, static_cast<Eigen::Index>(k));
    out.equilibrium.push_back(mean[k] + scale[k] * c0);
    std::vector<double> fitted(static_cast<std::size_t>(n));
    const Eigen::VectorXd model = fit.basis * fit.coefficients.col(static_cast<Eigen::Index>(k));
    for (int i = 0; i < n; ++i) fitted[i] = mean[k] + scale[k] * model(i);
    out.fitted.push_back(std::move(fitted));
    motion += (y.col(static_cast<Eigen::Index>(k)).array() - c0).square().sum();
  }
  out.residual = motion > 0.0 ? std::sqrt(fit.cost / motion) : 0.0;
  if (!oscillates) add_verdict(out.verdicts, IdentifyVerdict::not_oscillating);
  if (oscillates && *out.damped_frequency_hz * (n - 1) * h < kIdentifyMinCycles) {
    add_verdict(out.verdicts, IdentifyVerdict::too_short);
  }
  if (*out.residual > kIdentifyNoisyResidual) add_verdict(out.verdicts, IdentifyVerdict::too_noisy);
  return out;
}

Series decimate(const Series& x, const std::vector<std::size_t>& rows) {
  Series out(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    for (std::size_t r : rows) out[k].push_back(x[k][r]);
  }
  return out;
}

// The engine's step interval from the rows where each held step first shows: the least-squares slope of
// their times against step number (each shows up to one sample late; the slope averages that out).
double step_interval(const std::vector<std::size_t>& starts, double h) {
  std::vector<double> t;
  for (std::size_t r : starts) t.push_back(h * static_cast<double>(r));
  return fit_grid(t).interval;
}

}  // namespace

std::string_view identify_verdict_name(IdentifyVerdict v) {
  switch (v) {
    case IdentifyVerdict::too_short: return "too_short";
    case IdentifyVerdict::too_noisy: return "too_noisy";
    case IdentifyVerdict::not_oscillating: return "not_oscillating";
    case IdentifyVerdict::non_uniform_sampling: return "non_uniform_sampling";
    case IdentifyVerdict::clipped: return "clipped";
  }
  return "unknown";
}

std::optional<RecordingError> validate_recording(const Recording& r) {
  if (r.time_s.size() < 2) return RecordingError{r.time_s.size(), 0, "must have at least two rows"};
  if (r.time_s.size() > kIdentifyMaxSamples) return RecordingError{kIdentifyMaxSamples, 0, "must have at most 100000 rows"};
  if (r.probes.empty()) return RecordingError{0, 1, "must have at least one probe column beside time"};
  if (r.probes.size() > kIdentifyMaxProbes) return RecordingError{0, kIdentifyMaxProbes + 1, "must have at most 16 probe columns"};
  if (r.time_s.size() * r.probes.size() > kIdentifyMaxCells) {
    return RecordingError{kIdentifyMaxCells / r.probes.size(), 0, "must hold at most 400000 values (rows x probes)"};
  }
  for (std::size_t k = 0; k < r.probes.size(); ++k) {
    if (r.probes[k].size() != r.time_s.size()) {
      return RecordingError{std::min(r.probes[k].size(), r.time_s.size()), k + 1, "must be as long as the time column"};
    }
  }
  for (std::size_t i = 0; i < r.time_s.size(); ++i) {
    if (!std::isfinite(r.time_s[i])) return RecordingError{i, 0, "must be a finite number of seconds"};
    if (i > 0 && !(r.time_s[i] > r.time_s[i - 1])) return RecordingError{i, 0, "must be later than the previous row's time"};
    for (std::size_t k = 0; k < r.probes.size(); ++k) {
      if (!std::isfinite(r.probes[k][i])) return RecordingError{i, k + 1, "must be a finite number"};
    }
  }
  // Times so close that their intervals round to nothing relative to the span cannot be told apart.
  if (!((r.time_s.back() - r.time_s.front()) / static_cast<double>(r.time_s.size()) > 1e-12 * std::abs(r.time_s.back()))) {
    return RecordingError{r.time_s.size() - 1, 0, "must span more than rounding: the time steps are too small for their offset"};
  }
  return std::nullopt;
}

Identification identify(const Recording& r) {
  Identification out;
  out.samples = r.time_s.size();
  const Grid grid = fit_grid(r.time_s);
  out.sample_interval_s = grid.interval;
  out.sample_rate_hz = 1.0 / grid.interval;
  out.grid_deviation = grid.deviation;
  double h = grid.interval;
  Series x;
  if (grid.deviation > kIdentifyGridTolerance) {
    out.resampled = true;
    add_verdict(out.verdicts, IdentifyVerdict::non_uniform_sampling);
    x = resample(r, h);
  } else {
    x = r.probes;
  }
  out.fit_interval_s = h;
  out.joint = fit_motion(x, h);
  if (!out.resampled) {
    const std::vector<std::size_t> starts = held_steps(x);
    if (starts.size() > kIdentifyMinSamples) {
      const double step = step_interval(starts, h);
      const Series steps = decimate(x, starts);
      MotionFit held = fit_motion(steps, step);
      const bool better = held.residual && (!out.joint.residual || *held.residual < kHoldGain * *out.joint.residual);
      if (better) {
        out.step_rate_hz = 1.0 / step;
        out.fit_interval_s = step;
        out.joint = std::move(held);
        x = steps;
        h = step;
      }
    }
  }
  if (x.size() == 1) {
    out.probes.push_back(out.joint);
  } else {
    for (const auto& probe : x) out.probes.push_back(fit_motion(Series{probe}, h));
  }
  for (IdentifyVerdict v : out.joint.verdicts) add_verdict(out.verdicts, v);
  for (const MotionFit& probe : out.probes) {
    for (IdentifyVerdict v : probe.verdicts) add_verdict(out.verdicts, v);
  }
  return out;
}

}  // namespace softtune
