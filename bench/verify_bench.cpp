// `softtune verify` in every real engine linked in process (Box2D 2.4.1, ODE, Bullet, MuJoCo) for 10
// simulated seconds at 60 fps, plain and exact parameters. Target (issue 15): under 20 ms for all of them.
// The baseline in the same run is the tune alone, which every verify starts with.
#include <benchmark/benchmark.h>

#include "softtune/engines/verify.h"

namespace {

softtune::TuneRequest request() {
  softtune::TuneRequest r;
  r.frequency_hz = 5.0;
  r.damping_ratio = 0.1;
  r.effective_mass = 2.0;
  r.mode = softtune::SoftMode::exact;
  return r;
}

void BM_TuneAlone(benchmark::State& state) {
  const softtune::TuneRequest r = request();
  for (auto _ : state) benchmark::DoNotOptimize(softtune::tune(r));
}
BENCHMARK(BM_TuneAlone);

// -1: every engine in one verify; 0..: one engine each (the label names it).
void BM_Verify10Seconds(benchmark::State& state) {
  const softtune::TuneRequest r = request();
  const auto engines = softtune::engines::real_engines();
  const int only = static_cast<int>(state.range(0));
  softtune::engines::VerifyOptions options;
  options.duration_s = 10.0;
  for (auto _ : state) {
    const softtune::TuneResult tuned = softtune::tune(r);
    for (std::size_t i = 0; i < engines.size(); ++i) {
      if (only >= 0 && static_cast<int>(i) != only) continue;
      benchmark::DoNotOptimize(softtune::engines::verify_engine(*engines[i], tuned, r, options));
    }
  }
  state.SetLabel(state.range(0) < 0 ? "all engines" : std::string(engines[static_cast<std::size_t>(only)]->name));
}
BENCHMARK(BM_Verify10Seconds)->DenseRange(-1, 3)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
