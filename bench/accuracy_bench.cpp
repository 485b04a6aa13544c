// Speed targets of the accuracy report and the stability sweep (issue #4): the whole default accuracy
// report under 20 ms, the default sweep under 2 s. Each benchmark also reports its time as a multiple
// of the baseline (a bare loop of kBaselineSteps semi-implicit Euler steps) measured in the same run,
// both in thread CPU time.
#include <benchmark/benchmark.h>

#include <ctime>
#include <numbers>

#include "box2d_spring.h"
#include "softtune/accuracy.h"
#include "softtune/integrators.h"
#include "softtune/sequential_impulse.h"
#include "softtune/stability_sweep.h"

namespace {

using namespace softtune;

constexpr int kBaselineSteps = 100000;

// This thread's CPU time in seconds: on a shared machine wall time mostly measures the neighbours.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

State bare_loop(int steps) {
  const Oscillator o{1.0, 3947.8, 0.0};
  State s{1.0, 0.0};
  for (int i = 0; i < steps; ++i) s = semi_implicit_euler_step(s, o, 1.0 / 60.0);
  return s;
}

// Seconds of one baseline loop, as BM_Baseline_SemiImplicitLoop measured it (it runs first); when it
// was filtered out, the mean of 200 runs measured here.
double g_baseline_seconds = 0.0;

double baseline_seconds() {
  if (g_baseline_seconds > 0.0) return g_baseline_seconds;
  for (int r = 0; r < 20; ++r) benchmark::DoNotOptimize(bare_loop(kBaselineSteps));
  const int runs = 200;
  const double start = cpu_seconds();
  for (int r = 0; r < runs; ++r) benchmark::DoNotOptimize(bare_loop(kBaselineSteps));
  g_baseline_seconds = (cpu_seconds() - start) / runs;
  return g_baseline_seconds;
}

void report_ratio(benchmark::State& state, double total_seconds) {
  const double per_iteration = total_seconds / static_cast<double>(state.iterations());
  state.counters["cpu_ms"] = per_iteration * 1e3;
  state.counters["x_baseline"] = per_iteration / baseline_seconds();
}

// The default report of the example: 10 Hz free at 60 fps, 1 kg, default step rates and substeps.
AccuracySettings ten_hz_free() {
  AccuracySettings s;
  s.mass = 1.0;
  s.omega = 2.0 * std::numbers::pi * 10.0;
  s.damping_ratio = 0.0;
  s.duration_s = 0.3;  // 3 periods
  return s;
}

template <typename F>
void timed(benchmark::State& state, F&& body) {
  double total = 0.0;
  for (auto _ : state) {
    const double start = cpu_seconds();
    body();
    total += cpu_seconds() - start;
  }
  report_ratio(state, total);
}

void BM_Baseline_SemiImplicitLoop(benchmark::State& state) {
  double total = 0.0;
  for (auto _ : state) {
    const double start = cpu_seconds();
    benchmark::DoNotOptimize(bare_loop(kBaselineSteps));
    total += cpu_seconds() - start;
  }
  g_baseline_seconds = total / static_cast<double>(state.iterations());
  report_ratio(state, total);
}
BENCHMARK(BM_Baseline_SemiImplicitLoop)->Unit(benchmark::kMillisecond);

void BM_AccuracyReport_Default(benchmark::State& state) {
  const AccuracySettings s = ten_hz_free();
  timed(state, [&] { benchmark::DoNotOptimize(run_accuracy(s).rows.size()); });
}
BENCHMARK(BM_AccuracyReport_Default)->Unit(benchmark::kMillisecond);

void BM_AccuracyReport_WithBox2D(benchmark::State& state) {
  AccuracySettings s = ten_hz_free();
  s.engine = EngineRunner{kBox2DRowName, run_box2d_spring};
  timed(state, [&] { benchmark::DoNotOptimize(run_accuracy(s).rows.size()); });
}
BENCHMARK(BM_AccuracyReport_WithBox2D)->Unit(benchmark::kMillisecond);

void BM_StabilitySweep_Default(benchmark::State& state) {
  const SweepSettings s = default_sweep_settings();
  timed(state, [&] { benchmark::DoNotOptimize(run_sweep(s).summary.cases); });
}
BENCHMARK(BM_StabilitySweep_Default)->Unit(benchmark::kMillisecond)->Iterations(3);

// The grid-only answers (issue #20's baseline): no step limits, chain limits read off the scan.
void BM_StabilitySweep_GridOnly(benchmark::State& state) {
  SweepSettings s = default_sweep_settings();
  s.step_limits = false;
  ChainSweepSettings c = default_chain_sweep_settings();
  c.bisect = false;
  timed(state, [&] {
    benchmark::DoNotOptimize(run_sweep(s).summary.cases);
    benchmark::DoNotOptimize(run_chain_sweep(c).cases.size());
  });
}
BENCHMARK(BM_StabilitySweep_GridOnly)->Unit(benchmark::kMillisecond)->Iterations(3);

// What `softtune stability` runs: the sweep with its bisected step limits and the chain in four solvers
// with bisected, simulation-confirmed limits (target: under 2 s).
void BM_StabilitySweep_DefaultWithChain(benchmark::State& state) {
  const SweepSettings s = default_sweep_settings();
  const ChainSweepSettings c = default_chain_sweep_settings();
  timed(state, [&] {
    benchmark::DoNotOptimize(run_sweep(s).summary.cases);
    benchmark::DoNotOptimize(run_chain_sweep(c).cases.size());
  });
}
BENCHMARK(BM_StabilitySweep_DefaultWithChain)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
