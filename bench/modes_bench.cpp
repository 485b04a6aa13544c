// The modal tuning of the vehicle (settle, linearise and solve, twice: scene/modal_tuning.h) against one
// `simulate` of the same car (run_scene of vehicle_per_spring: 6 s of Box2D with probes and fits), alternated in
// one benchmark so the ratio is measured under the same conditions; and the pieces on their own: the
// linearisation (a Box2D settle) and the modes of the linear model (reduce + eigenproblems).
#include <benchmark/benchmark.h>

#include <ctime>

#include <Eigen/Eigenvalues>
#include <nlohmann/json.hpp>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/modes.h"
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

// The largest legal modes request (kMaxModeBodies: 100 boxes dropped on one spot, every pair in contact):
// each stage's CPU time, and the longest of the pieces the run-time limit cannot interrupt (one Eigen
// solve: the undamped, continuous and discrete eigenproblems and the null-space SVD, measured on their own
// at the size this scene gives), so the limit's overrun is known (docs/limits-and-security.md).
Scene crowded_boxes() {
  nlohmann::json bodies = nlohmann::json::array();
  for (int i = 0; i < 100; ++i) {
    bodies.push_back({{"id", "b" + std::to_string(i)},
                      {"shape", {{"type", "box"}, {"width", 1}, {"height", 1}}},
                      {"mass", 1},
                      {"position", {0.001 * (i % 10), 0.001 * (i / 10)}}});
  }
  return codec::decode_scene({{"name", "crowded"},
                              {"world", {{"fps", 60}, {"duration_s", 2.0 / 60}, {"gravity", {0, -10}},
                                         {"bounds", {-1000, -1000, 1000, 1000}}}},
                              {"bodies", bodies}});
}

void BM_CrowdedModesStages(benchmark::State& state) {
  const Scene scene = crowded_boxes();
  double linearise_s = 0.0, reduce_s = 0.0, modes_s = 0.0;
  std::size_t rows = 0;
  Eigen::Index dofs = 0;
  for (auto _ : state) {
    double t0 = cpu_seconds();
    LinearisedScene lin;
    linearise_scene(scene, MassModel::effective, {}, lin);
    double t1 = cpu_seconds();
    const modes::ReducedSystem reduced = modes::reduce(lin.model);
    double t2 = cpu_seconds();
    benchmark::DoNotOptimize(modes::modes_of(lin.model, reduced, lin.h).size());
    const double t3 = cpu_seconds();
    linearise_s += t1 - t0;
    reduce_s += t2 - t1;
    modes_s += t3 - t2;
    rows = lin.model.rows.size();
    dofs = reduced.null_space.cols();
  }
  const double n = static_cast<double>(state.iterations());
  state.counters["linearise_ms"] = 1e3 * linearise_s / n;
  state.counters["reduce_ms"] = 1e3 * reduce_s / n;
  state.counters["modes_ms"] = 1e3 * modes_s / n;
  state.counters["rows"] = static_cast<double>(rows);
  state.counters["dofs"] = static_cast<double>(dofs);
}
BENCHMARK(BM_CrowdedModesStages)->Unit(benchmark::kMillisecond)->Iterations(2);

// One non-symmetric eigen-solve of the continuous state matrix at the body cap (100 free bodies: 300
// degrees of freedom, 600 x 600): the longest piece of modes_of between two run-limit checks.
void BM_LargestEigenSolve(benchmark::State& state) {
  const Eigen::Index d = 300;
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(2 * d, 2 * d);
  for (auto _ : state) {
    Eigen::EigenSolver<Eigen::MatrixXd> solver(a);
    benchmark::DoNotOptimize(solver.eigenvalues().size());
  }
}
BENCHMARK(BM_LargestEigenSolve)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
