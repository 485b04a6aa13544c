#include "softtune/accuracy.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "softtune/analytic.h"
#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"
#include "softtune/trajectory_fit.h"

namespace softtune {

double steady_clock_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

TrajectoryError trajectory_error(const std::vector<double>& x, double dt, double omega, double zeta) {
  TrajectoryError e;
  if (x.size() < 2) return e;
  const double x0 = x.front();
  double sum_sq = 0.0;
  for (std::size_t n = 1; n < x.size(); ++n) {
    const double exact = analytic_state({x0, 0.0}, omega, zeta, static_cast<double>(n) * dt).x;
    const double err = std::abs(x[n] - exact) / std::abs(x0);
    e.max_error = std::max(e.max_error, err);
    sum_sq += err * err;
  }
  e.rms_error = std::sqrt(sum_sq / static_cast<double>(x.size() - 1));
  return e;
}

namespace {

// Positions once per frame of `method` with `substeps` steps per frame; stops early once blown up.
std::vector<double> simulate_frames(Method method, const StepModel& model, int substeps, int frames) {
  std::vector<double> x;
  x.reserve(static_cast<std::size_t>(frames) + 1);
  State s{kStandardX0, 0.0};
  x.push_back(s.x);
  for (int f = 0; f < frames; ++f) {
    for (int i = 0; i < substeps; ++i) s = step(method, s, model);
    x.push_back(s.x);
    if (!(std::abs(s.x) <= kBlowUpAmplitude * kStandardX0) || !std::isfinite(s.v)) break;
  }
  return x;
}

// What the timed loop runs: the same steps, no recording. The result feeds a sink so it is not elided.
double run_steps(Method method, const StepModel& model, long long steps) {
  State s{kStandardX0, 0.0};
  for (long long i = 0; i < steps; ++i) s = step(method, s, model);
  return s.x;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Median over `repeats` batches of the seconds one call of `run` takes; a batch repeats it `per_batch`
// times.
template <typename Run>
double median_seconds(const AccuracySettings& s, int per_batch, Run&& run) {
  std::vector<double> samples;
  for (int r = 0; r < std::max(1, s.timing_repeats); ++r) {
    const double start = s.clock();
    for (int i = 0; i < per_batch; ++i) run();
    samples.push_back(std::max(0.0, s.clock() - start) / per_batch);
  }
  return median(std::move(samples));
}

// Scores a trajectory sampled once per frame: errors, blow-up and the fitted poles.
void score(AccuracyRow& row, const std::vector<double>& x, const AccuracySettings& s) {
  const double frame_dt = 1.0 / row.fps;
  const bool stopped_early = static_cast<int>(x.size()) < row.frames + 1;
  bool finite = !stopped_early;
  for (double v : x) finite = finite && std::isfinite(v) && std::abs(v) <= kBlowUpAmplitude * kStandardX0;
  const auto fit = finite ? fit_trajectory_poles(x, frame_dt) : std::nullopt;
  row.blew_up = !finite || (fit && fit->spectral_radius > 1.0 + kGrowthTolerance);
  if (fit) {
    row.trajectory_frequency_hz = fit->frequency_hz;
    row.trajectory_damping_ratio = fit->damping_ratio;
  }
  if (!row.blew_up) {
    const TrajectoryError e = trajectory_error(x, frame_dt, s.omega, s.damping_ratio);
    row.max_error = e.max_error;
    row.rms_error = e.rms_error;
  }
  row.positions = x;
}

AccuracyRow core_row(Method method, double fps, int substeps, const AccuracySettings& s) {
  AccuracyRow row;
  row.method = method_name(method);
  row.core_method = method;
  row.fps = fps;
  row.substeps = substeps;
  row.h = step_size(fps, substeps);
  row.frames = std::max(1, static_cast<int>(std::lround(s.duration_s * fps)));
  const StepModel model = make_step_model(s.mass, s.omega, s.damping_ratio, row.h);
  score(row, simulate_frames(method, model, substeps, row.frames), s);

  const DiscreteAnalysis a = analyze(method, model, s.omega, s.damping_ratio);
  row.pole_frequency_hz = a.achieved_frequency_hz;
  row.pole_damping_ratio = a.achieved_damping_ratio;
  row.pole_spectral_radius = a.spectral_radius;

  const long long steps = static_cast<long long>(row.frames) * substeps;
  const int per_batch = static_cast<int>(std::max<long long>(1, (s.min_steps_per_batch + steps - 1) / steps));
  volatile double sink = 0.0;  // keeps the timed runs observable to the optimizer
  const double seconds = median_seconds(s, per_batch, [&] { sink = run_steps(method, model, steps); });
  row.cpu_seconds_per_sim_second = seconds / (row.frames / fps);
  return row;
}

AccuracyRow engine_row(const EngineRunner& engine, double fps, const AccuracySettings& s) {
  AccuracyRow row;
  row.method = engine.name;
  row.fps = fps;
  row.h = 1.0 / fps;
  row.frames = std::max(1, static_cast<int>(std::lround(s.duration_s * fps)));
  const SpringConstants k = spring_constants(s.mass, s.omega, s.damping_ratio);
  const Oscillator spring{s.mass, k.stiffness, k.damping};
  std::vector<double> x = engine.run(spring, kStandardX0, row.h, row.frames);
  score(row, x, s);
  // An engine step costs microseconds: one run per batch is well above the clock's resolution.
  volatile double sink = 0.0;
  const double seconds = median_seconds(s, 1, [&] { sink = engine.run(spring, kStandardX0, row.h, row.frames).back(); });
  row.cpu_seconds_per_sim_second = seconds / (row.frames / fps);
  return row;
}

}  // namespace

Recommendation recommend(const std::vector<AccuracyRow>& rows, double error_budget) {
  Recommendation r;
  r.error_budget = error_budget;
  std::optional<double> cheapest;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const AccuracyRow& row = rows[i];
    if (row.blew_up || !row.max_error) continue;
    if (!r.most_accurate || *row.max_error < *rows[*r.most_accurate].max_error) r.most_accurate = i;
    if (*row.max_error > error_budget) continue;
    ++r.rows_meeting_budget;
    if (!cheapest || row.cpu_seconds_per_sim_second < *cheapest) cheapest = row.cpu_seconds_per_sim_second;
  }
  if (!cheapest) return r;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const AccuracyRow& row = rows[i];
    if (row.blew_up || !row.max_error || *row.max_error > error_budget) continue;
    if (row.cpu_seconds_per_sim_second > *cheapest * r.cost_tie_factor) continue;
    if (!r.row || *row.max_error < *rows[*r.row].max_error) r.row = i;
  }
  return r;
}

AccuracyReport run_accuracy(const AccuracySettings& s) {
  AccuracyReport report;
  report.duration_s = s.duration_s;
  for (double fps : s.step_rates_hz) {
    for (Method m : kAllMethods) {
      const bool soft = m == Method::soft || m == Method::soft_exact;
      if (!soft) {
        report.rows.push_back(core_row(m, fps, 1, s));
        continue;
      }
      for (int n : s.soft_substeps) report.rows.push_back(core_row(m, fps, n, s));
    }
    if (s.engine) report.rows.push_back(engine_row(*s.engine, fps, s));
  }
  report.recommendation = recommend(report.rows, s.error_budget);
  return report;
}

}  // namespace softtune
