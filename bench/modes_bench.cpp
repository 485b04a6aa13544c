// The modal tuning of the vehicle (settle, linearise and solve, twice: scene/modal_tuning.h) against one
// `simulate` of the same car (run_scene of vehicle_per_spring: 6 s of Box2D with probes and fits), alternated in
// one benchmark so the ratio is measured under the same conditions; and the pieces on their own: the
// linearisation (a Box2D settle) and the modes of the linear model (reduce + eigenproblems).
#include <benchmark/benchmark.h>

#include <ctime>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/scene/linearise.h"
#include "softtune/scene/modal_tuning.h"
#include "softtune/scene/runner.h"

namespace {

using namespace softtune;
using namespace softtune::scene;

Scene load(const std::string& name) { return codec::decode_scene(app::load_preset(SOFTTUNE_PRESETS_DIR, name)); }

// Thread CPU time: the machine is shared, and a preempted loop must not count as slow.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

double solve(const Scene& vehicle) {
  ModalTuningResult out;
  Scene tuned;
  StageList stages;
  tune_modes(vehicle, MassModel::effective, out, tuned, stages);
  return out.groups.at(0).stiffness;
}

void BM_ModalSolveVsSimulate(benchmark::State& state) {
  const Scene vehicle = load("vehicle"), simulated = load("vehicle_per_spring");
  double solve_s = 0.0, simulate_s = 0.0;
  bool solve_first = true;
  for (auto _ : state) {
    for (int k = 0; k < 2; ++k) {
      const double t0 = cpu_seconds();
      if ((k == 0) == solve_first) {
        benchmark::DoNotOptimize(solve(vehicle));
        solve_s += cpu_seconds() - t0;
      } else {
        benchmark::DoNotOptimize(run_scene(simulated).probes.size());
        simulate_s += cpu_seconds() - t0;
      }
    }
    solve_first = !solve_first;
  }
  state.counters["solve_over_simulate"] = solve_s / simulate_s;
  state.counters["solve_ms"] = 1e3 * solve_s / state.iterations();
  state.counters["simulate_ms"] = 1e3 * simulate_s / state.iterations();
}
BENCHMARK(BM_ModalSolveVsSimulate)->Unit(benchmark::kMillisecond);

void BM_Linearise(benchmark::State& state) {
  const Scene vehicle = load("vehicle_per_spring");
  for (auto _ : state) {
    LinearisedScene lin;
    linearise_scene(vehicle, MassModel::effective, {}, lin);
    benchmark::DoNotOptimize(lin.model.rows.size());
  }
}
BENCHMARK(BM_Linearise)->Unit(benchmark::kMillisecond);

void BM_ModesOfLinearModel(benchmark::State& state) {
  LinearisedScene lin;
  linearise_scene(load("vehicle_per_spring"), MassModel::effective, {}, lin);
  for (auto _ : state) benchmark::DoNotOptimize(modes::modes_of(lin.model, modes::reduce(lin.model), lin.h).size());
}
BENCHMARK(BM_ModesOfLinearModel)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
