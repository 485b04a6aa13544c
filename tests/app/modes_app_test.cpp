// `softtune modes` and POST /api/v1/modes (server/app/modes_app.cpp) on the real presets, and the refusals of
// the modes request and of a scene's modal tuning, each naming its field.
#include "app/modes_app.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/preset_store.h"
#include "app/simulate_app.h"
#include "codec/problem.h"
#include "../presets_dir.h"
#include "softtune/support/run_limit.h"

namespace softtune::app {
namespace {

using nlohmann::json;

using test_support::kPresets;

std::string problem_field(const std::function<json()>& run) {
  try {
    run();
  } catch (const codec::Problem& p) {
    return p.field;
  }
  return "(no problem)";
}

const json& mode_named(const json& answer, const std::string& name) {
  for (const json& m : answer["modes"]) {
    if (m["name"] == name) return m;
  }
  ADD_FAILURE() << "no mode " << name;
  return answer["modes"][0];
}

TEST(ModesApp, VehiclePerSpringHeavesOnTheDocsClosedForm) {
  const json out = run_modes({{"preset", "vehicle_per_spring"}}, kPresets);
  EXPECT_EQ(out["stages"], (json{"validate", "settle", "linearise", "modes"}));
  EXPECT_EQ(out["bodies"], 15);
  // Heave on two springs tuned at 3 Hz on m_eff = 1 / (1/M + 1/m_w + d^2/I) each, wheels held by the road:
  // f sqrt(2 m_eff / M) (docs/scenes.md).
  const double m_eff = 1.0 / (1.0 / 120.0 + 1.0 / 15.0 + 1.1 * 1.1 / 92.5);
  const json& heave = mode_named(out, "chassis heave");
  EXPECT_NEAR(heave["continuous"]["frequency_hz"].get<double>(), 3.0 * std::sqrt(2.0 * m_eff / 120.0), 5e-3);
  EXPECT_EQ(heave["components"][0]["body"], "chassis");
  EXPECT_EQ(heave["components"][0]["coordinate"], "y");
  EXPECT_TRUE(out["modes"][0]["free"]);  // the car rolls
  EXPECT_TRUE(out["modes"][0]["continuous"].is_null());
}

TEST(ModesApp, ModalVehicleReportsTheModesItRunsWith) {
  const json out = run_modes({{"preset", "vehicle"}}, kPresets);
  EXPECT_EQ(out["stages"], (json{"validate", "settle", "linearise", "modes", "modal_solve", "settle", "linearise", "modes"}));
  const json& heave = mode_named(out, "chassis heave");
  EXPECT_NEAR(heave["discrete"]["frequency_hz"].get<double>(), 3.0, 0.01);  // the exact solve at the new rest
  EXPECT_NEAR(heave["discrete"]["damping_ratio"].get<double>(), 0.5, 0.01);
}

TEST(ModesApp, RefusesBadRequestsNamingTheField) {
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "vehicle"}, {"at_s", 100}}, kPresets); }), "at_s");
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "vehicle"}, {"at_s", "soon"}}, kPresets); }), "at_s");
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "oscillator"}}, kPresets); }), "bodies");
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "vehicle"}, {"extra", 1}}, kPresets); }), "extra");
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "vehicle"}, {"engine", "havok"}}, kPresets); }), "engine");
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "vehicle"}, {"engine_settings", {{"noSuchSetting", 1}}}}, kPresets); }),
            "engine_settings.noSuchSetting");
}

// The modes answer names the engine whose step was linearised: the default, Box2D 2.4, named or not.
TEST(ModesApp, TheAnswerNamesTheEngine) {
  const json named = run_modes({{"preset", "vehicle_per_spring"}, {"engine", "box2d_v2_4"}}, kPresets);
  EXPECT_EQ(named, run_modes({{"preset", "vehicle_per_spring"}}, kPresets));
  EXPECT_EQ(named["engine"]["name"], "box2d_v2_4");
  EXPECT_FALSE(named["engine"]["version"].get<std::string>().empty());
  // Another engine's step is not linearised: refused naming `engine`, never Box2D's modes under its name.
  EXPECT_EQ(problem_field([] { return run_modes({{"preset", "vehicle_per_spring"}, {"engine", "ode"}}, kPresets); }), "engine");
}

json vehicle_with(const json& target) {
  json scene = load_preset(kPresets, "vehicle");
  scene["modal_tuning"]["targets"] = json::array({target});
  return scene;
}

TEST(ModesApp, RefusesModalTargetsItCannotReachNamingThem) {
  // Beyond Nyquist at 60 fps in exact mode.
  json t = {{"mode", "heave"}, {"body", "chassis"}, {"frequency_hz", 40}, {"damping_ratio", 0.1}};
  EXPECT_EQ(problem_field([&] { return run_simulate({{"scene", vehicle_with(t)}}, kPresets); }), "modal_tuning.targets.0.frequency_hz");
  // A box of the stack: its contacts hold it, no mode moves it.
  t = {{"mode", "heave"}, {"body", "box_0_0"}, {"frequency_hz", 2}, {"damping_ratio", 0.5}};
  EXPECT_EQ(problem_field([&] { return run_simulate({{"scene", vehicle_with(t)}}, kPresets); }), "modal_tuning.targets.0");
  t = {{"mode", "wobble"}, {"body", "chassis"}, {"frequency_hz", 2}, {"damping_ratio", 0.5}};
  EXPECT_EQ(problem_field([&] { return run_simulate({{"scene", vehicle_with(t)}}, kPresets); }), "scene.modal_tuning.targets.0.mode");  // the schema's rule, as a dotted path
  t = {{"mode", "heave"}, {"body", "ground"}, {"frequency_hz", 2}, {"damping_ratio", 0.5}};
  EXPECT_EQ(problem_field([&] { return run_simulate({{"scene", vehicle_with(t)}}, kPresets); }), "scene.modal_tuning.targets.0.body");
  t = {{"mode", "heave"}, {"body", "chassis"}, {"damping_ratio", 0.5}};  // no frequency: the tune codec's rule
  EXPECT_EQ(problem_field([&] { return run_simulate({{"scene", vehicle_with(t)}}, kPresets); }), "scene.modal_tuning.targets.0.response_frames");
  json scene = load_preset(kPresets, "vehicle");
  scene["modal_tuning"]["groups"][0]["joints"].push_back("rear_suspension");
  EXPECT_EQ(problem_field([&] { return run_simulate({{"scene", scene}}, kPresets); }), "scene.modal_tuning.groups.0.joints.2");
}

}  // namespace
}  // namespace softtune::app

namespace softtune::app {
namespace {

// `bodies` free boxes on one spot, linearised at t = 0 (before any step, so no contacts: every body
// free, the eigenproblems at their largest for that count, 6 x bodies square).
json modes_limit_crowd(int bodies) {
  json list = json::array();
  for (int i = 0; i < bodies; ++i) {
    list.push_back({{"id", "b" + std::to_string(i)},
                    {"shape", {{"type", "box"}, {"width", 1}, {"height", 1}}},
                    {"mass", 1},
                    {"position", {0.001 * (i % 10), 0.001 * (i / 10)}}});
  }
  return {{"name", "crowd"},
          {"world", {{"fps", 60}, {"duration_s", 1.0}, {"gravity", {0, -10}}, {"bounds", {-1000, -1000, 1000, 1000}}}},
          {"bodies", list},
          {"at_s", 0}};
}

}  // namespace

// The modes' solve checks the run-time limit between its stages (the null-space reduction's rows and each
// eigenproblem): with no Box2D step to check (at_s 0), a request under a limit of a fifth of its own run
// stops before its last eigenproblem, instead of running to the end.
TEST(ModesApp, TheSolveStopsAtTheRunLimit) {
  const json request = modes_limit_crowd(50);
  const double t0 = support::thread_cpu_seconds();
  EXPECT_EQ(run_modes(request, kPresets)["bodies"], 50);
  const double whole = support::thread_cpu_seconds() - t0;
  bool stopped = false;
  const double t1 = support::thread_cpu_seconds();
  try {
    const support::ScopedRunLimit limit({whole / 5, nullptr, {}});
    run_modes(request, kPresets);
  } catch (const support::RunStopped& e) {
    stopped = e.why == support::RunStopped::Why::budget;
  }
  const double spent = support::thread_cpu_seconds() - t1;
  EXPECT_TRUE(stopped) << "the whole solve took " << whole << " s of CPU";
  EXPECT_LT(spent, 0.8 * whole) << "stopped after " << spent << " s, the whole solve " << whole << " s";
}

}  // namespace softtune::app
