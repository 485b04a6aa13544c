// The scene price (server/app/scene_cost.h: what simulate and preview are charged against the 2 s budget
// before any step) against the CPU time the run really takes, over a spread of scenes: every preset, bodies
// kept apart (no contacts) at 8 and 100 velocity iterations, a long joint chain, and crowds dropped on one
// spot. Prints measured / price per case, and exits 1 when a case without crowding priced at 1 % of the
// budget or more (0.02 s: below it the run is too short to time and its miss too small to matter) is outside
// 2x (0.5 to 2). Where a scene's cost is
// its contacts, which no count made before the run can see (a crowd's pairs, up to n^2 / 2, and how long they
// stay in contact), the ratio is shown, not asserted: the run-time limit bounds those
// (docs/limits-and-security.md "Run-time limits").
#include <benchmark/benchmark.h>

#include <cstdio>
#include <ctime>
#include <string>

#include <nlohmann/json.hpp>

#include "app/preset_store.h"
#include "app/scene_cost.h"
#include "codec/scene_codec.h"
#include "softtune/scene/runner.h"

namespace {

using namespace softtune;
using nlohmann::json;

double thread_cpu() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

json world(double duration_s, int velocity_iterations) {
  return {{"fps", 60}, {"duration_s", duration_s}, {"gravity", {0, -10}}, {"velocity_iterations", velocity_iterations},
          {"bounds", {-10000, -10000, 10000, 10000}}};
}

// `n` circles 3 m apart on a grid, falling freely: no contacts.
json apart(int n, double duration_s, int iterations) {
  json bodies = json::array();
  for (int i = 0; i < n; ++i) {
    bodies.push_back({{"id", "b" + std::to_string(i)}, {"shape", {{"type", "circle"}, {"radius", 0.5}}}, {"mass", 1},
                      {"position", {3.0 * (i % 25), 3.0 * (i / 25)}}});
  }
  return {{"name", "apart"}, {"world", world(duration_s, iterations)}, {"bodies", bodies}};
}

// `n` circles on one spot: every pair in contact at first.
json crowd(int n, double duration_s) {
  json bodies = json::array();
  for (int i = 0; i < n; ++i) {
    bodies.push_back({{"id", "b" + std::to_string(i)}, {"shape", {{"type", "circle"}, {"radius", 0.5}}}, {"mass", 1},
                      {"position", {0.001 * (i % 10), 0.001 * (i / 10)}}});
  }
  return {{"name", "crowd"}, {"world", world(duration_s, 8)}, {"bodies", bodies}};
}

// A hanging chain of `n` links, each pinned to the one above (joints: no contacts between links).
json hanging_chain(int n, double duration_s, int iterations) {
  json bodies = json::array({{{"id", "ceiling"}, {"static", true}, {"shape", {{"type", "box"}, {"width", 2}, {"height", 0.2}}},
                              {"position", {0, 10.1}}}});
  json joints = json::array();
  for (int i = 0; i < n; ++i) {
    const std::string id = "link_" + std::to_string(i);
    bodies.push_back({{"id", id}, {"shape", {{"type", "box"}, {"width", 0.1}, {"height", 0.5}}}, {"mass", 1.0},
                      {"position", {0.0, 10.0 - 0.25 - 0.5 * i}}, {"angle", i == 0 ? 0.15 : 0.0}});
    const double y = 10.0 - 0.5 * i;
    joints.push_back({{"id", "pin_" + std::to_string(i)}, {"type", "revolute"},
                      {"body_a", i == 0 ? std::string("ceiling") : "link_" + std::to_string(i - 1)}, {"body_b", id},
                      {"anchor_a", {0.0, y}}, {"anchor_b", {0.0, y}}});
  }
  json w = world(duration_s, iterations);
  w["bounds"] = {-100, -100, 100, 100};
  return {{"name", "chain"}, {"world", w}, {"bodies", bodies}, {"joints", joints}};
}

struct PriceCase {
  std::string name;
  json scene;  // a scene document, or {"preset": NAME}
  bool contacts_dominate = false;
};

// Cases held to the 2x bar (not crowded, priced at kHeldFromSeconds or more) that missed it.
constexpr double kHeldFromSeconds = 0.02;
int g_missed = 0;

void BM_ScenePriceVsMeasured(benchmark::State& state, const PriceCase& c) {
  const json doc = c.scene.contains("preset") ? app::load_preset(SOFTTUNE_PRESETS_DIR, c.scene["preset"]) : c.scene;
  const scene::Scene s = codec::decode_scene(doc);
  const double price = app::scene_cost(s, {}, "").cpu_seconds;
  double measured = 0.0;
  for (auto _ : state) {
    const double t0 = thread_cpu();
    benchmark::DoNotOptimize(scene::run_scene(s).probes.size());
    measured += thread_cpu() - t0;
  }
  measured /= static_cast<double>(state.iterations());
  const double ratio = measured / price;
  state.counters["price_s"] = price;
  state.counters["measured_s"] = measured;
  state.counters["measured_over_price"] = ratio;
  const bool within = ratio >= 0.5 && ratio <= 2.0;
  const bool held = !c.contacts_dominate && price >= kHeldFromSeconds;
  if (held && !within) ++g_missed;
  state.counters["within_2x"] = within ? 1 : 0;
  std::printf("price-vs-measured %-38s price %.4f s measured %.4f s ratio %.2f %s\n", c.name.c_str(), price,
              measured, ratio,
              c.contacts_dominate ? "(contacts: bounded at run time)"
              : !held             ? (within ? "within 2x (too short to hold)" : "outside 2x (too short to hold)")
              : within            ? "within 2x, held"
                                  : "OUTSIDE 2x, held: FAIL");
}

const PriceCase kCases[] = {
    {"preset oscillator", {{"preset", "oscillator"}}},
    {"preset buddhas", {{"preset", "buddhas"}}},
    {"preset mouse", {{"preset", "mouse"}}},
    {"preset stiff", {{"preset", "stiff"}}},
    {"preset chain", {{"preset", "chain"}}},
    {"preset bridge", {{"preset", "bridge"}}},
    {"preset heavy_on_light", {{"preset", "heavy_on_light"}}},
    {"preset vehicle_per_spring", {{"preset", "vehicle_per_spring"}}},
    {"100 apart, 8 iterations, 60 s", apart(100, 60, 8)},
    {"500 apart, 8 iterations, 30 s", apart(500, 30, 8)},
    {"100 apart, 100 iterations, 30 s", apart(100, 30, 100)},
    {"100-link chain, 8 iterations, 20 s", hanging_chain(100, 20, 8)},
    {"100-link chain, 100 iterations, 10 s", hanging_chain(100, 10, 100)},
    {"50 on one spot, 20 s", crowd(50, 20), true},
    {"200 on one spot, 2 s", crowd(200, 2), true},
    {"500 on one spot, 0.5 s", crowd(500, 0.5), true},
};

}  // namespace

int main(int argc, char** argv) {
  for (const PriceCase& c : kCases) {
    benchmark::RegisterBenchmark(("BM_ScenePriceVsMeasured/" + c.name).c_str(),
                                 [&c](benchmark::State& st) { BM_ScenePriceVsMeasured(st, c); })
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::printf("price-vs-measured: %d held case(s) outside 2x\n", g_missed);
  return g_missed == 0 ? 0 : 1;
}
