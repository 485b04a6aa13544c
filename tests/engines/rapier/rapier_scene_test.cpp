// Scenes in the real Rapier 2-D through the C++ backend and the node worker (engines/rapier/rapier_scene.cpp,
// rapier_scene.mjs): the five acceptance points of a scene backend (docs/scene-backends.md).
//   1. one body on one soft joint against k, c on the body's mass: analytic, and Rapier's own 1-D model;
//   2. the vehicle preset at Box2D 2.4's 3 Hz / zeta 0.5 springs: settles, heaves near 3 Hz, drives into the
//      boxes; its f, zeta and ms per run printed next to Box2D 2.4's, run in this process;
//   3. every preset builds and runs finite, or is refused naming a feature;
//   4. a refusal names the field and the engine;   5. parse(fields(k, c)) round trip, a missing field named.
#include "rapier_scene.h"

#include <box2d/box2d.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "node_scene.h"
#include "codec/scene_codec.h"
#include "softtune/engines/engine_model.h"
#include "softtune/response_fit.h"
#include "softtune/scene/box2d_scene.h"

namespace softtune::scene {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
const SceneBackend& kRapierTestBackend = kRapierSceneBackend;

engines::SettingValues rapier_test_defaults() {
  engines::SettingValues v;
  for (const engines::SettingSpec& s : kRapierTestBackend.settings) v.push_back(s.default_value);
  return v;
}

std::unique_ptr<SceneWorld> rapier_test_build(const Scene& s, std::vector<std::optional<JointSpring>> springs,
                                              std::optional<FieldError>& error) {
  const SceneBuild build{&s, std::move(springs), rapier_test_defaults()};
  return kRapierTestBackend.build(build, error);
}

Scene rapier_test_preset(const std::string& name) {
  std::ifstream in(std::string(SOFTTUNE_SOURCE_DIR) + "/presets/" + name + ".json");
  return codec::decode_scene(nlohmann::json::parse(in));
}

int rapier_test_body(const Scene& s, const std::string& id) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

BodySettings rapier_test_box(const std::string& id, bool is_static, Eigen::Vector2d at, double mass) {
  BodySettings b;
  b.id = id;
  b.is_static = is_static;
  if (!is_static) b.mass = mass;
  b.shape.width = 0.2;
  b.shape.height = 0.2;
  b.position = at;
  return b;
}

// What Rapier's own 1-D model (core/src/engines/rapier.cpp: the ForceBased motor, implicit in each of the
// numSolverIterations substeps of h / 4) predicts for k, c on mass m at 60 fps: the substeps' implicit Euler
// adds about omega h / 8 to the damping ratio (0.026 at 2 Hz), which the analytic oscillator does not have.
engines::Prediction rapier_test_model(double m, const JointSpring& spring) {
  const engines::EngineModel* model = engines::find_engine_model("rapier");
  engines::SettingValues values = engines::default_settings(*model);
  values[2] = 1;  // motorModel ForceBased, as the scene builds its motors
  engines::Target t;
  t.effective_mass = m;
  t.omega = std::sqrt(spring.stiffness / m);
  t.damping_ratio = spring.damping / (2.0 * m * t.omega);
  t.dt = 1.0 / 60.0;
  t.spring = {spring.stiffness, spring.damping};
  return model->report(t, values).predicted;
}

// k, c of f Hz and zeta on mass m.
JointSpring rapier_test_spring(double m, double f, double zeta) {
  const double w = kTwoPi * f;
  return {m * w * w, 2.0 * m * zeta * w};
}

TEST(RapierScene, DistanceSpringHangingBoxMatchesTheAnalyticOscillator) {
  Scene s;
  s.world.gravity = {0, -10};
  s.bodies = {rapier_test_box("top", true, {0, 0}, 0), rapier_test_box("bob", false, {0, -1.1}, 2.0)};
  JointSettings j;
  j.id = "hanger";
  j.kind = JointKind::distance;
  j.body_a = "top";
  j.body_b = "bob";
  j.anchor_a = {0, 0};
  j.anchor_b = {0, -1.1};
  j.length = 1.0;
  s.joints = {j};
  std::optional<FieldError> error;
  auto world = rapier_test_build(s, {rapier_test_spring(2.0, 2.0, 0.1)}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  std::vector<double> y{world->body(1).centre.y()};
  for (int f = 0; f < 180; ++f) {
    world->step_frame(f);
    y.push_back(world->body(1).centre.y());
  }
  const ResponseFit fit = fit_response(y, 1.0 / 60.0);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  const engines::Prediction p = rapier_test_model(2.0, rapier_test_spring(2.0, 2.0, 0.1));
  std::printf("rapier distance spring: f %.4f Hz (model %.4f, analytic 2), zeta %.4f (model %.4f, analytic 0.1)\n",
              *fit.frequency_hz, *p.frequency_hz, *fit.damping_ratio, *p.damping_ratio);
  EXPECT_NEAR(*fit.frequency_hz, 2.0, 0.02);  // 1 % of the analytic frequency
  EXPECT_NEAR(*fit.frequency_hz, *p.frequency_hz, 0.01 * *p.frequency_hz);
  EXPECT_NEAR(*fit.damping_ratio, *p.damping_ratio, 0.01);
  EXPECT_NEAR(*fit.equilibrium, -1.0 - 2.0 * 10.0 / rapier_test_spring(2.0, 2.0, 0.1).stiffness, 2e-3);
}

TEST(RapierScene, WheelSpringOnASliderMatchesTheAnalyticOscillator) {
  Scene s;
  s.world.gravity = {0, 0};
  s.bodies = {rapier_test_box("rail", true, {0, 0}, 0), rapier_test_box("cart", false, {1, 0}, 3.0)};
  s.bodies[1].linear_velocity = {0.3, 0};
  JointSettings j;
  j.id = "slider";
  j.kind = JointKind::wheel;
  j.body_a = "rail";
  j.body_b = "cart";
  j.anchor_b = {1, 0};
  j.axis = {1, 0};
  s.joints = {j};
  std::optional<FieldError> error;
  auto world = rapier_test_build(s, {rapier_test_spring(3.0, 1.5, 0.2)}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  std::vector<double> x{world->body(1).centre.x()};
  double drift = 0.0;
  for (int f = 0; f < 180; ++f) {
    world->step_frame(f);
    x.push_back(world->body(1).centre.x());
    drift = std::max(drift, std::abs(world->body(1).centre.y()));
  }
  const ResponseFit fit = fit_response(x, 1.0 / 60.0);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  const engines::Prediction p = rapier_test_model(3.0, rapier_test_spring(3.0, 1.5, 0.2));
  std::printf("rapier wheel spring: f %.4f Hz (model %.4f, analytic 1.5), zeta %.4f (model %.4f, analytic 0.2)\n",
              *fit.frequency_hz, *p.frequency_hz, *fit.damping_ratio, *p.damping_ratio);
  // The suspension carries the whole cart (half on the hub, half on the wheel body).
  EXPECT_NEAR(*fit.frequency_hz, 1.5, 0.015);
  EXPECT_NEAR(*fit.frequency_hz, *p.frequency_hz, 0.01 * *p.frequency_hz);
  EXPECT_NEAR(*fit.damping_ratio, *p.damping_ratio, 0.01);
  EXPECT_NEAR(*fit.equilibrium, 1.0, 1e-3);
  EXPECT_LT(drift, 1e-3);  // rigid across the axis
}

struct RapierTestVehicleRun {
  std::vector<double> heave;  // chassis centre y, frames 0..120 (0-2 s)
  double x_at_2s = 0, x_at_6s = 0, box_push = 0, ms = 0;
  bool finite = true;
};

constexpr JointSpring kVehicleSpring{24842.07, 914.753};

template <class Step, class Read>
RapierTestVehicleRun rapier_test_drive(const Scene& s, Step step, Read read) {
  RapierTestVehicleRun run;
  const int chassis = rapier_test_body(s, "chassis"), box = rapier_test_body(s, "box_0_0");
  const double box_x0 = s.bodies[box].position.x();
  run.heave.push_back(read(chassis).y());
  const auto t0 = std::chrono::steady_clock::now();
  for (int f = 0; f < frame_count(s.world); ++f) {
    step(f);
    const Eigen::Vector2d c = read(chassis);
    run.finite = run.finite && c.allFinite();
    if (f < 120) run.heave.push_back(c.y());
    if (f == 119) run.x_at_2s = c.x();
    run.box_push = std::max(run.box_push, read(box).x() - box_x0);
  }
  run.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  run.x_at_6s = read(chassis).x();
  return run;
}

TEST(RapierScene, VehicleSettlesHeavesNear3HzAndDrivesIntoTheBoxes) {
  Scene s = rapier_test_preset("vehicle");
  ASSERT_EQ(s.joints.size(), 2u);
  std::optional<FieldError> error;
  auto world = rapier_test_build(s, {kVehicleSpring, kVehicleSpring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  const RapierTestVehicleRun rapier = rapier_test_drive(
      s, [&](int f) { world->step_frame(f); }, [&](int i) { return world->body(static_cast<std::size_t>(i)).centre; });

  // Box2D 2.4 with the same k, c typed into its wheel joints, in this process.
  Scene typed = s;
  typed.modal_tuning.reset();
  for (JointSettings& j : typed.joints) {
    j.tuning.reset();
    j.typed = TypedSpring{kVehicleSpring.stiffness, kVehicleSpring.damping};
  }
  Box2DScene box2d(typed, typed.mass_model);
  ASSERT_FALSE(box2d.error());
  const RapierTestVehicleRun b2 = rapier_test_drive(
      typed, [&](int f) { box2d.step_frame(f); },
      [&](int i) {
        const b2Vec2 c = box2d.bodies()[static_cast<std::size_t>(i)]->GetWorldCenter();
        return Eigen::Vector2d(c.x, c.y);
      });

  const ResponseFit fr = fit_response(rapier.heave, 1.0 / 60.0), fb = fit_response(b2.heave, 1.0 / 60.0);
  ASSERT_TRUE(fr.frequency_hz && fr.damping_ratio && fb.frequency_hz && fb.damping_ratio);
  std::printf("vehicle heave: rapier f %.3f Hz zeta %.3f | box2d_v2_4 f %.3f Hz zeta %.3f\n", *fr.frequency_hz,
              *fr.damping_ratio, *fb.frequency_hz, *fb.damping_ratio);
  std::printf("vehicle 6 s at 60 fps: rapier %.1f ms, box2d_v2_4 %.1f ms (ratio %.1f); chassis x at 6 s: rapier %.2f m, box2d %.2f m\n",
              rapier.ms, b2.ms, rapier.ms / b2.ms, rapier.x_at_6s, b2.x_at_6s);
  EXPECT_TRUE(rapier.finite);
  EXPECT_NEAR(*fr.frequency_hz, 3.0, 0.3);
  EXPECT_NEAR(*fr.damping_ratio, 0.5, 0.15);
  // Settled on its wheels: the chassis sits at its static sag below the start (m g / 2k per spring, < 5 cm).
  EXPECT_NEAR(rapier.heave.back(), s.bodies[1].position.y() - 120.0 * 10.0 / (2 * kVehicleSpring.stiffness), 0.02);
  EXPECT_NEAR(rapier.x_at_2s, 0.0, 0.05);  // no motor before 2 s
  EXPECT_GT(rapier.x_at_6s, 8.0);          // the motor drives it right, past the boxes' first column at 9 m
  EXPECT_GT(rapier.box_push, 0.3);         // and it pushes into them
}

TEST(RapierScene, EveryPresetRunsFiniteOrIsRefusedNamingAFeature) {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(SOFTTUNE_SOURCE_DIR) + "/presets")) {
    const std::string name = entry.path().stem().string();
    if (entry.path().extension() != ".json" || name == "schema") continue;
    const Scene s = rapier_test_preset(name);
    // Each soft joint's spring as Box2D 2.4 tunes it from the preset's request.
    Box2DScene box2d(s, s.mass_model);
    ASSERT_FALSE(box2d.error()) << name;
    std::vector<std::optional<JointSpring>> springs;
    for (const JointTuning& t : box2d.tunings()) {
      springs.push_back(t.soft() ? std::optional<JointSpring>(JointSpring{t.stiffness, t.damping}) : std::nullopt);
    }
    std::optional<FieldError> error;
    auto world = rapier_test_build(s, springs, error);
    if (!world) {
      ASSERT_TRUE(error) << name;
      EXPECT_TRUE(error->field.starts_with("joints.") || error->field.starts_with("bodies.")) << name << ": " << error->field;
      EXPECT_NE(error->rule.find("rapier"), std::string::npos) << name << ": " << error->rule;
      std::printf("%s: refused, %s: %s\n", name.c_str(), error->field.c_str(), error->rule.c_str());
      continue;
    }
    bool finite = true;
    for (int f = 0; f < frame_count(s.world) && finite; ++f) {
      world->step_frame(f);
      for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const BodyState b = world->body(i);
        finite = finite && b.centre.allFinite() && b.velocity.allFinite() && std::isfinite(b.angle);
      }
    }
    EXPECT_TRUE(finite) << name;
    std::printf("%s: ran %d frames finite\n", name.c_str(), frame_count(s.world));
  }
}

TEST(RapierScene, AFeatureRapierCannotBuildIsRefusedNamingFieldAndEngine) {
  Scene s;
  s.bodies = {rapier_test_box("rail", true, {0, 0}, 0), rapier_test_box("cart", false, {1, 0}, 3.0)};
  JointSettings j;
  j.id = "slider";
  j.kind = JointKind::wheel;
  j.body_a = "rail";
  j.body_b = "cart";
  j.anchor_b = {1, 0};
  s.joints = {j};
  std::optional<FieldError> error;
  EXPECT_FALSE(rapier_test_build(s, {std::nullopt}, error));  // a rigid wheel joint: no suspension spring
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "joints.0.spring");
  EXPECT_NE(error->rule.find("rapier"), std::string::npos) << error->rule;
}

TEST(RapierScene, FieldsParseBackAndAMissingFieldIsNamed) {
  const Scene s = rapier_test_preset("vehicle");
  const engines::SettingValues settings = rapier_test_defaults();
  const engines::Parameters typed = kRapierTestBackend.fields(s, 0, kVehicleSpring, settings);
  FieldError error;
  const auto back = kRapierTestBackend.parse(s, 0, typed, settings, error);
  ASSERT_TRUE(back) << error.field;
  EXPECT_EQ(back->stiffness, kVehicleSpring.stiffness);
  EXPECT_EQ(back->damping, kVehicleSpring.damping);
  EXPECT_FALSE(kRapierTestBackend.parse(s, 0, {{"JointMotor::stiffness", 10.0}}, settings, error));
  EXPECT_EQ(error.field, "JointMotor::damping");
}

TEST(RapierScene, StepRoundTripsAgainstOneRunOp) {
  // The per-frame round trip against one "run" op of the same 360 frames, on the shared worker.
  const Scene s = rapier_test_preset("vehicle");
  const nlohmann::json request = node_worker::build_request(
      "rapier", kRapierTestBackend.settings, SceneBuild{&s, {kVehicleSpring, kVehicleSpring}, rapier_test_defaults()});
  node_worker::NodeWorker& worker = node_worker::shared_worker();
  const int a = worker.call(request)["world"].get<int>(), b = worker.call(request)["world"].get<int>();
  const auto t0 = std::chrono::steady_clock::now();
  nlohmann::json last;
  for (int f = 0; f < 360; ++f) last = worker.call({{"op", "step"}, {"world", a}, {"frame", f}});
  const auto t1 = std::chrono::steady_clock::now();
  const nlohmann::json run = worker.call({{"op", "run"}, {"world", b}, {"frame", 0}, {"frames", 360}});
  const auto t2 = std::chrono::steady_clock::now();
  const double step_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  const double run_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  std::printf("vehicle in rapier: 360 step round trips %.1f ms, one run op %.1f ms\n", step_ms, run_ms);
  ASSERT_EQ(run["frames"].size(), 360u);
  EXPECT_EQ(run["frames"][359], last["bodies"]);  // the same engine, the same steps: the same states
  worker.call({{"op", "destroy"}, {"world", a}});
  worker.call({{"op", "destroy"}, {"world", b}});
}

// A run that reads no contacts steps ahead in `run` round trips (node_scene.cpp): frame for frame the same
// states as a run that steps one frame per call, and in less time.
TEST(RapierScene, SteppingAheadGivesTheSameStatesFrameByFrame) {
  const Scene s = rapier_test_preset("vehicle");
  std::optional<FieldError> error;
  SceneBuild one_by_one{&s, {kVehicleSpring, kVehicleSpring}, rapier_test_defaults(), true};
  SceneBuild ahead = one_by_one;
  ahead.contacts = false;
  std::unique_ptr<SceneWorld> a = kRapierTestBackend.build(one_by_one, error), b = kRapierTestBackend.build(ahead, error);
  ASSERT_TRUE(a && b);
  const int chassis = rapier_test_body(s, "chassis");
  double a_ms = 0.0, b_ms = 0.0;
  for (int f = 0; f < 150; ++f) {
    const auto t0 = std::chrono::steady_clock::now();
    a->step_frame(f);
    const auto t1 = std::chrono::steady_clock::now();
    b->step_frame(f);
    const auto t2 = std::chrono::steady_clock::now();
    a_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
    b_ms += std::chrono::duration<double, std::milli>(t2 - t1).count();
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
      ASSERT_EQ(a->body(i).centre, b->body(i).centre) << "frame " << f << " body " << s.bodies[i].id;
      ASSERT_EQ(a->body(i).angle, b->body(i).angle) << "frame " << f;
    }
  }
  EXPECT_NE(a->body(chassis).centre, s.bodies[chassis].position);  // it moved
  std::printf("vehicle in rapier, 150 frames: one call per frame %.1f ms, stepping ahead %.1f ms\n", a_ms, b_ms);
}

}  // namespace
}  // namespace softtune::scene
