// Identification speed (issue 19): identify() on a 10,000-sample recording against the Prony fit alone
// (fit_response) on the same samples, in the same run. The recording: a lightly damped 2 Hz oscillator
// sampled at 60 Hz with 1 % noise, so every sample is in the fit window. Report: BM_Identify / BM_PronyFit.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "softtune/analytic.h"
#include "softtune/identify.h"
#include "softtune/response_fit.h"

namespace {

softtune::Recording recording(std::size_t samples, std::size_t probes) {
  std::mt19937 rng(19);
  std::normal_distribution<double> noise(0.0, 0.01);
  softtune::Recording r;
  r.probes.resize(probes);
  for (std::size_t n = 0; n < samples; ++n) {
    const double t = static_cast<double>(n) / 60.0;
    r.time_s.push_back(t);
    for (auto& p : r.probes) p.push_back(softtune::analytic_state({1.0, 0.0}, 2.0 * std::numbers::pi * 2.0, 0.002, t).x + noise(rng));
  }
  return r;
}

void BM_PronyFit(benchmark::State& state) {
  const softtune::Recording r = recording(10'000, 1);
  for (auto _ : state) benchmark::DoNotOptimize(softtune::fit_response(r.probes[0], 1.0 / 60.0));
}
BENCHMARK(BM_PronyFit)->Unit(benchmark::kMicrosecond);

void BM_Identify(benchmark::State& state) {
  const softtune::Recording r = recording(10'000, static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(softtune::identify(r));
}
BENCHMARK(BM_Identify)->Arg(1)->Arg(4)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
