// `softtune check` at the rates a game ships: the seven presets at 30, 60, 120 and 144 fps (28 cases), on the
// check use case's thread pool with -j 2 against -j 1 in the same run. BM_CheckJobs/N times one; BM_Speedup
// runs both alternately (order flipped every iteration) and reports wall(-j 1) / wall(-j 2), and the CPU time
// each spent, so a neighbour's load on this shared machine hits both the same way.
#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>

#include "app/check_app.h"
#include "app/preset_store.h"

namespace {

using namespace softtune;

std::vector<app::CheckInput> presets() {
  return app::presets_from_paths({SOFTTUNE_PRESETS_DIR}, SOFTTUNE_PRESETS_DIR);
}

app::CheckOptions options(int jobs) {
  app::CheckOptions o;
  o.fps = {30, 60, 120, 144};
  o.jobs = jobs;
  return o;
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

void BM_CheckJobs(benchmark::State& state) {
  const auto inputs = presets();
  const app::CheckOptions o = options(static_cast<int>(state.range(0)));
  std::size_t cases = 0;
  for (auto _ : state) cases = app::run_checks(inputs, o).cases.size();
  state.counters["cases"] = static_cast<double>(cases);
  state.counters["cases_per_s"] = benchmark::Counter(static_cast<double>(cases * state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CheckJobs)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Speedup(benchmark::State& state) {
  const auto inputs = presets();
  double wall[3] = {0, 0, 0}, cpu[3] = {0, 0, 0};
  bool one_first = true;
  for (auto _ : state) {
    for (int k = 0; k < 2; ++k) {
      const int jobs = (k == 0) == one_first ? 1 : 2;
      const double c0 = process_cpu_seconds();
      const auto t0 = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(app::run_checks(inputs, options(jobs)).passed);
      wall[jobs] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      cpu[jobs] += process_cpu_seconds() - c0;
    }
    one_first = !one_first;
  }
  state.counters["speedup_j2_over_j1"] = wall[1] / wall[2];
  state.counters["j1_ms"] = 1e3 * wall[1] / state.iterations();
  state.counters["j2_ms"] = 1e3 * wall[2] / state.iterations();
  state.counters["cpu_ratio_j2_over_j1"] = cpu[2] / cpu[1];
}
BENCHMARK(BM_Speedup)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();
