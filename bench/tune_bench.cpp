// The full tune (designer mapping, softness in every form, exact poles, discrete analysis of all five
// integrators, engine export) against a bare k, c, gamma, beta computation in the same run.
// Target (issue 2): full tune median under 1 us, aim 300 ns.
#include <benchmark/benchmark.h>

#include "softtune/tune.h"

namespace {

softtune::TuneRequest request(softtune::SoftMode mode) {
  softtune::TuneRequest r;
  r.response_frames = 12;
  r.oscillation = softtune::Oscillation::some;
  r.effective_mass = 2.0;
  r.mode = mode;
  return r;
}

void BM_BareSpringAndSoftness(benchmark::State& state) {
  double frames = 12.0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(frames);
    const double omega = softtune::angular_frequency(softtune::frequency_from_frames(frames, 60.0));
    const softtune::SpringConstants s = softtune::spring_constants(2.0, omega, 0.5);
    benchmark::DoNotOptimize(softtune::softness_from_spring(s.stiffness, s.damping, 1.0 / 60.0));
  }
}
BENCHMARK(BM_BareSpringAndSoftness);

void BM_FullTuneStandard(benchmark::State& state) {
  const softtune::TuneRequest r = request(softtune::SoftMode::standard);
  for (auto _ : state) benchmark::DoNotOptimize(softtune::tune(r));
}
BENCHMARK(BM_FullTuneStandard);

void BM_FullTuneExact(benchmark::State& state) {
  const softtune::TuneRequest r = request(softtune::SoftMode::exact);
  for (auto _ : state) benchmark::DoNotOptimize(softtune::tune(r));
}
BENCHMARK(BM_FullTuneExact);

void BM_FullTuneConstraint(benchmark::State& state) {
  softtune::TuneRequest r = request(softtune::SoftMode::standard);
  r.effective_mass.reset();
  softtune::Constraint2D c;
  c.body_a.is_static = true;
  c.body_b.mass = 4.0;
  c.body_b.inertia = 1.0;
  c.anchor_b = {0.5, 0.0};
  c.axis = {0.0, 1.0};
  r.constraint = c;
  for (auto _ : state) benchmark::DoNotOptimize(softtune::tune(r));
}
BENCHMARK(BM_FullTuneConstraint);

}  // namespace

BENCHMARK_MAIN();
