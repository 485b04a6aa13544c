// Per preset: simulated seconds per wall second of the scene runner, and its overhead against a raw Box2D
// stepping loop of the same world in the same run (goal: overhead <= 1.1x). The raw loop builds the same world
// (Box2DScene: bodies, tuned joints) and calls b2World::Step itself, switching wheel motors on at the same
// frames; the runner adds probe sampling, joint-error and bounds checks every frame and the response fit.
// Core-integrator oscillators (the 1-D oscillator, the stiff scene's comparison) are stepped directly with
// step() in the raw loop too.
#include <benchmark/benchmark.h>

#include <cmath>
#include <ctime>
#include <memory>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/scene/box2d_scene.h"
#include "softtune/scene/runner.h"

namespace {

using namespace softtune;
using namespace softtune::scene;

// vehicle_per_spring, not vehicle: the raw loop cannot repeat the modal solve the vehicle runs first.
const char* const kPresets[] = {"oscillator", "buddhas", "mouse", "stiff", "chain", "bridge", "vehicle_per_spring"};

Scene load(const std::string& name) { return codec::decode_scene(app::load_preset(SOFTTUNE_PRESETS_DIR, name)); }

// The core oscillators of a scene stepped directly; a joint-linked one takes the joint's tuning and mass.
double raw_core(const Scene& scene, const std::vector<JointTuning>& joints) {
  double sink = 0.0;
  for (const OscillatorSettings& o : scene.oscillators) {
    TuneRequest q;
    if (o.joint.empty()) {
      q = *o.tuning;
      q.effective_mass = o.effective_mass;
    } else {
      for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        if (scene.joints[j].id != o.joint) continue;
        q = *scene.joints[j].tuning;
        q.effective_mass = joints[j].model_mass;
      }
    }
    q.fps = scene.world.fps;
    q.substeps = scene.world.substeps;
    const TuneResult t = tune(q);
    const StepModel model = make_step_model(t.effective_mass, t.omega, t.damping_ratio, t.h);
    State s{o.initial_displacement, o.initial_velocity};
    for (int f = 0; f < frame_count(scene.world) * scene.world.substeps && std::abs(s.x) < kDivergence; ++f) s = step(o.method, s, model);
    sink += s.x;
  }
  return sink;
}

double raw(const Scene& scene) {
  if (scene.bodies.empty()) return raw_core(scene, {});
  Box2DScene built(scene, scene.mass_model);
  b2World& world = built.world();
  const WorldSettings& w = scene.world;
  const float dt = static_cast<float>(step_size(w.fps, w.substeps));
  const int frames = frame_count(w);
  for (int f = 0; f < frames; ++f) {
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
      const JointSettings& s = scene.joints[j];
      if (s.kind == JointKind::wheel && s.max_motor_torque > 0.0 && f / w.fps >= s.motor_start_s)
        static_cast<b2WheelJoint*>(built.joints()[j])->EnableMotor(true);
    }
    for (int k = 0; k < w.substeps; ++k) world.Step(dt, w.velocity_iterations, w.position_iterations);
  }
  return world.GetBodyList()->GetPosition().x + raw_core(scene, built.tunings());
}

void BM_Raw(benchmark::State& state, const char* name) {
  const Scene scene = load(name);
  for (auto _ : state) benchmark::DoNotOptimize(raw(scene));
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(scene.world.duration_s * state.iterations(), benchmark::Counter::kIsRate);
}

void BM_Runner(benchmark::State& state, const char* name) {
  const Scene scene = load(name);
  for (auto _ : state) benchmark::DoNotOptimize(run_scene(scene).probes.size());
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(scene.world.duration_s * state.iterations(), benchmark::Counter::kIsRate);
}

// Thread CPU time, not wall time: the machine is shared, and a preempted loop must not count as slow.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

// Both loops alternately (order flipped every iteration) in one benchmark, so the ratio is measured under the
// same conditions.
void BM_Overhead(benchmark::State& state, const char* name) {
  const Scene scene = load(name);
  double raw_s = 0.0, runner_s = 0.0;
  bool raw_first = true;
  for (auto _ : state) {
    for (int k = 0; k < 2; ++k) {
      const double t0 = cpu_seconds();
      if ((k == 0) == raw_first) {
        benchmark::DoNotOptimize(raw(scene));
        raw_s += cpu_seconds() - t0;
      } else {
        benchmark::DoNotOptimize(run_scene(scene).probes.size());
        runner_s += cpu_seconds() - t0;
      }
    }
    raw_first = !raw_first;
  }
  state.counters["overhead"] = runner_s / raw_s;
  state.counters["runner_sim_s_per_cpu_s"] = scene.world.duration_s * state.iterations() / runner_s;
  state.counters["raw_sim_s_per_cpu_s"] = scene.world.duration_s * state.iterations() / raw_s;
}

const bool kRegistered = [] {
  for (const char* name : kPresets) {
    benchmark::RegisterBenchmark((std::string("BM_Raw/") + name).c_str(), BM_Raw, name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_Runner/") + name).c_str(), BM_Runner, name)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark((std::string("BM_Overhead/") + name).c_str(), BM_Overhead, name)->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace

BENCHMARK_MAIN();
