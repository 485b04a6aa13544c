// The full tune (designer mapping, softness in every form, exact poles, discrete analysis of all five
// integrators, engine export) against a bare k, c, gamma, beta computation in the same run.
// Target (issue 2): full tune median under 1 us, aim 300 ns. Issue 15: the engine models (every
// engines.<name> report) add at most 2 us: BM_EngineReports* time them alone, per engine and all together,
// for the same target the full tune builds, so the tune without them is the difference.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "softtune/engines/engine_model.h"
#include "softtune/engines/godot_3d.h"
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

// The target tune() hands the models, from a tune of the same request.
softtune::engines::Target target_of(const softtune::TuneRequest& r) {
  const softtune::TuneResult t = softtune::tune(r);
  softtune::engines::Target target;
  target.effective_mass = t.effective_mass;
  target.omega = t.omega;
  target.damping_ratio = t.damping_ratio;
  target.dt = t.h;
  target.spring = t.spring;
  return target;
}

void engine_reports(benchmark::State& state, softtune::SoftMode mode, double zeta) {
  softtune::TuneRequest r = request(mode);
  r.oscillation.reset();
  r.damping_ratio = zeta;
  const softtune::engines::Target target = target_of(r);
  const auto models = softtune::engines::engine_models();
  std::vector<softtune::engines::SettingValues> defaults;
  for (const auto* m : models) defaults.push_back(softtune::engines::default_settings(*m));
  const int only = static_cast<int>(state.range(0));
  for (auto _ : state) {
    for (std::size_t i = 0; i < models.size(); ++i) {
      if (only >= 0 && static_cast<int>(i) != only) continue;
      benchmark::DoNotOptimize(models[i]->report(target, defaults[i]));
    }
  }
  if (only >= 0) state.SetLabel(std::string(models[static_cast<std::size_t>(only)]->name));
}

void BM_EngineReportsExact(benchmark::State& state) { engine_reports(state, softtune::SoftMode::exact, 0.5); }
void BM_EngineReportsStandard(benchmark::State& state) { engine_reports(state, softtune::SoftMode::standard, 0.5); }
void BM_EngineReportsUndamped(benchmark::State& state) { engine_reports(state, softtune::SoftMode::exact, 0.0); }
// -1: all models together; 0..n-1: one engine each (the label names it), every registered model.
BENCHMARK(BM_EngineReportsExact)->DenseRange(-1, static_cast<int>(softtune::engines::engine_models().size()) - 1);
BENCHMARK(BM_EngineReportsStandard)->Arg(-1);

// godot_3d, not yet in engine_models() for its cost (issue 33): its report alone, at the same targets, with
// chipmunk's (the same semi-implicit step without the spring-dropping branch) as the baseline.
void model_report(benchmark::State& state, const softtune::engines::EngineModel& model) {
  softtune::TuneRequest r = request(state.range(0) == 0 ? softtune::SoftMode::exact : softtune::SoftMode::standard);
  r.oscillation.reset();
  r.damping_ratio = 0.5;
  const softtune::engines::Target target = target_of(r);
  const softtune::engines::SettingValues defaults = softtune::engines::default_settings(model);
  for (auto _ : state) benchmark::DoNotOptimize(model.report(target, defaults));
  state.SetLabel(std::string(model.name));
}
void BM_Godot3DReport(benchmark::State& state) { model_report(state, softtune::engines::kGodot3DModel); }
void BM_Godot3DBaseline(benchmark::State& state) {
  model_report(state, *softtune::engines::find_engine_model("chipmunk"));
}
// 0: exact mode, 1: standard.
BENCHMARK(BM_Godot3DReport)->Arg(0)->Arg(1);
BENCHMARK(BM_Godot3DBaseline)->Arg(0)->Arg(1);
BENCHMARK(BM_EngineReportsUndamped)->Arg(-1);

}  // namespace

BENCHMARK_MAIN();
