// Each registered scene backend (engines/scene_backends.h) against Box2D 2.4 in the same run: the vehicle as a
// designer simulates it (`simulate` of the vehicle preset, 6 s at 60 fps: its modal solve, the run in the engine,
// the answer's JSON), and the stepping alone (`run_scene` of vehicle_per_spring, whose joints carry their own
// tuning: no modal solve first). Each benchmark runs the engine and Box2D alternately (order flipped every
// iteration), so the ratio is measured under the same load; wall time, not thread CPU time, because a backend
// behind the node worker (Jolt, Rapier) spends its time in another process, and that round trip is part of its
// cost. Issue 32's aim: each engine within 3x Box2D's run for the vehicle.
#include <benchmark/benchmark.h>

#include <chrono>
#include <stdexcept>
#include <string>

#include "app/preset_store.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"
#include "softtune/engines/scene_backends.h"
#include "softtune/scene/runner.h"

namespace {

using namespace softtune;
using nlohmann::json;

double scene_backends_wall_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The engine's run and Box2D's alternately; counters: ms per run of each and their ratio.
template <typename Run>
void alternate(benchmark::State& state, const Run& run, const scene::SceneBackend* engine, const scene::SceneBackend* box2d) {
  double engine_s = 0.0, box2d_s = 0.0;
  bool engine_first = true;
  for (auto _ : state) {
    for (int k = 0; k < 2; ++k) {
      const bool is_engine = (k == 0) == engine_first;
      const double t0 = scene_backends_wall_s();
      run(is_engine ? engine : box2d);
      (is_engine ? engine_s : box2d_s) += scene_backends_wall_s() - t0;
    }
    engine_first = !engine_first;
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["engine_ms_per_run"] = 1e3 * engine_s / n;
  state.counters["box2d_ms_per_run"] = 1e3 * box2d_s / n;
  state.counters["x_box2d"] = engine_s / box2d_s;
}

void BM_SimulateVehicle(benchmark::State& state, const scene::SceneBackend* engine) {
  const scene::SceneBackend* box2d = engines::find_scene_backend("box2d_v2_4");
  alternate(state, [](const scene::SceneBackend* b) {
    const json answer = app::run_simulate({{"preset", "vehicle"}, {"engine", b->name}}, SOFTTUNE_PRESETS_DIR);
    benchmark::DoNotOptimize(answer.size());
  }, engine, box2d);
}

void BM_StepVehiclePerSpring(benchmark::State& state, const scene::SceneBackend* engine) {
  const scene::SceneBackend* box2d = engines::find_scene_backend("box2d_v2_4");
  const scene::Scene scene = codec::decode_scene(app::load_preset(SOFTTUNE_PRESETS_DIR, "vehicle_per_spring"));
  alternate(state, [&scene](const scene::SceneBackend* b) {
    scene::RunOptions options;
    options.backend = b;
    const scene::SceneResult result = scene::run_scene(scene, options);
    if (result.error) throw std::runtime_error(result.error->field + ": " + result.error->rule);
    benchmark::DoNotOptimize(result.probes.size());
  }, engine, box2d);
}

const bool kRegistered = [] {
  for (const scene::SceneBackend* b : engines::scene_backends()) {
    const std::string name(b->name);
    benchmark::RegisterBenchmark(("BM_SimulateVehicle/" + name).c_str(), BM_SimulateVehicle, b)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_StepVehiclePerSpring/" + name).c_str(), BM_StepVehiclePerSpring, b)->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
