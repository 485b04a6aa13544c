#pragma once
// The scenes the in-process scene backends' tests share (tests/engines/<engine>/<engine>_scene_test.cpp): a
// box hanging on a distance spring, a box on a wheel-joint slider, the vehicle with typed suspension, the
// presets, and the reference runs in Box2D 2.4 (scene/box2d_scene.h) next to which an engine is reported.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "codec/scene_codec.h"
#include "softtune/response_fit.h"
#include "softtune/scene/box2d_scene.h"
#include "softtune/scene/scene_world.h"

namespace softtune::test_support::scene_cases {

using scene::BodySettings;
using scene::JointKind;
using scene::JointSettings;
using scene::JointSpring;
using scene::Scene;
using scene::SceneBackend;
using scene::SceneBuild;
using scene::SceneWorld;
using scene::ShapeKind;

using Springs = std::vector<std::optional<JointSpring>>;

/// The suspension spring Box2D 2.4 needs for the vehicle's 3 Hz, zeta 0.5 heave (the modal tuning's answer).
inline constexpr double kVehicleStiffness = 24842.07;
inline constexpr double kVehicleDamping = 914.753;

inline Scene load_preset(const std::string& name) {
  std::ifstream in(std::string(SOFTTUNE_PRESETS_DIR) + "/" + name + ".json");
  return codec::decode_scene(nlohmann::json::parse(in));
}

inline std::vector<std::string> preset_names() {
  return {"bridge", "bridge_deck", "buddhas", "chain", "heavy_on_light", "mouse", "oscillator", "stiff",
          "vehicle", "vehicle_per_spring"};
}

inline BodySettings box_body(const std::string& id, Eigen::Vector2d at, double w, double h, bool is_static,
                             double mass = 1.0) {
  BodySettings b;
  b.id = id;
  b.shape.kind = ShapeKind::box;
  b.shape.width = w;
  b.shape.height = h;
  b.is_static = is_static;
  if (!is_static) b.mass = mass;
  b.position = at;
  return b;
}

/// A 2 kg box hanging 2 m below a static beam on a distance spring (anchors on the centres, so the spring
/// does not turn it), released at the rest length: it bobs about its sag m g / k.
inline Scene hanging_box() {
  Scene s;
  s.name = "hanging_box";
  s.bodies.push_back(box_body("beam", {0, 5}, 2.0, 0.2, true));
  s.bodies.push_back(box_body("box", {0, 3}, 0.5, 0.5, false, 2.0));
  JointSettings j;
  j.id = "spring";
  j.kind = JointKind::distance;
  j.body_a = "beam";
  j.body_b = "box";
  j.anchor_a = {0, 5};
  j.anchor_b = {0, 3};
  s.joints.push_back(j);
  return s;
}

/// A 3 kg box on a horizontal wheel joint to a static rail, no gravity, pushed along the axis and spun:
/// the spring oscillates it along x, the joint holds y, the rotation stays free.
inline Scene wheel_slider() {
  Scene s;
  s.name = "wheel_slider";
  s.world.gravity = {0, 0};
  s.bodies.push_back(box_body("rail", {0, 0}, 0.4, 0.4, true));
  BodySettings b = box_body("slider", {0, 0}, 0.6, 0.3, false, 3.0);
  b.linear_velocity = {0.5, 0};
  b.angular_velocity = 1.0;
  s.bodies.push_back(b);
  JointSettings j;
  j.id = "slide";
  j.kind = JointKind::wheel;
  j.body_a = "rail";
  j.body_b = "slider";
  j.anchor_b = {0, 0};
  j.axis = {1, 0};
  s.joints.push_back(j);
  return s;
}

/// A 2 kg box (inertia about its centre 2 (0.6^2 + 0.2^2) / 12 kg m^2) welded at its centre to a static post,
/// no gravity, spun at 0.5 rad/s: the weld's soft rotation swings it about its centre.
inline Scene welded_box() {
  Scene s;
  s.name = "welded_box";
  s.world.gravity = {0, 0};
  s.bodies.push_back(box_body("post", {0, 0}, 0.1, 0.1, true));
  BodySettings b = box_body("box", {0, 0}, 0.6, 0.2, false, 2.0);
  b.angular_velocity = 0.5;
  s.bodies.push_back(b);
  JointSettings j;
  j.id = "weld";
  j.kind = JointKind::weld;
  j.body_a = "post";
  j.body_b = "box";
  j.anchor_a = {0, 0};
  j.anchor_b = {0, 0};
  s.joints.push_back(j);
  return s;
}
inline constexpr double kWeldedBoxInertia = 2.0 * (0.6 * 0.6 + 0.2 * 0.2) / 12.0;

/// A 1.5 kg box held by an uncapped mouse joint at its centre, the target 0.3 m to its right, no gravity:
/// the pull swings it about the target.
inline Scene mouse_box() {
  Scene s;
  s.name = "mouse_box";
  s.world.gravity = {0, 0};
  s.bodies.push_back(box_body("box", {0, 1}, 0.4, 0.4, false, 1.5));
  JointSettings j;
  j.id = "pull";
  j.kind = JointKind::mouse;
  j.body_b = "box";
  j.anchor_b = {0, 1};
  j.target = {0.3, 1};
  s.joints.push_back(j);
  return s;
}

/// A triangle (its centroid 0.2 m above its base's middle, the body origin) dropped 0.3 m onto a static
/// ground box: it lands flat on its base and rests there.
inline Scene dropped_triangle() {
  Scene s;
  s.name = "dropped_triangle";
  s.bodies.push_back(box_body("ground", {0, -0.5}, 10.0, 1.0, true));
  BodySettings t;
  t.id = "triangle";
  t.shape.kind = ShapeKind::polygon;
  t.shape.vertices = {{-0.5, 0.0}, {0.5, 0.0}, {0.0, 0.6}};
  t.mass = 2.0;
  t.position = {0, 0.3};
  s.bodies.push_back(t);
  return s;
}

/// The preset starts the tyres where Box2D's contact solver leaves them: on the road's 1 cm polygon skin less
/// its 5 mm slop. Shapes without a skin (ODE's, Bullet's: their margins lie inside the shapes) touch the road
/// 5 mm lower; starting there keeps the landing out of the heave.
inline constexpr double kBox2DTyreLift = 0.005;

/// The vehicle preset with both suspensions typed at k, c (no modal tuning), the car lowered by `lower` m.
inline Scene typed_vehicle(double k, double c, double lower = 0.0) {
  Scene s = load_preset("vehicle");
  for (const char* id : {"chassis", "rear_wheel", "front_wheel"}) {
    for (BodySettings& b : s.bodies) {
      if (b.id == id) b.position.y() -= lower;
    }
  }
  for (JointSettings& j : s.joints) j.anchor_b.y() -= lower;
  s.modal_tuning.reset();
  for (JointSettings& j : s.joints) {
    j.tuning.reset();
    j.typed = scene::TypedSpring{k, c};
  }
  return s;
}

/// Each joint's spring as Box2D 2.4 tunes it (joint_tuning.h): what the runner gives a backend.
inline Springs box2d_springs(const Scene& s) {
  scene::Box2DScene box2d(s, s.mass_model);
  Springs out;
  for (const scene::JointTuning& t : box2d.tunings()) {
    out.push_back(t.soft() ? std::optional<JointSpring>(JointSpring{t.stiffness, t.damping}) : std::nullopt);
  }
  return out;
}

/// Builds `s` in the backend with its settings' defaults, or `settings` when given.
inline std::unique_ptr<SceneWorld> build_scene(const SceneBackend& backend, const Scene& s, const Springs& springs,
                                               std::optional<FieldError>& error,
                                               const engines::SettingValues& settings = {}) {
  SceneBuild b;
  b.scene = &s;
  b.springs = springs;
  b.settings = settings;
  if (b.settings.empty()) {
    for (const engines::SettingSpec& spec : backend.settings) b.settings.push_back(spec.default_value);
  }
  return backend.build(b, error);
}

/// Samples of `read` at frames 0..frames (frame 0 the start), stepping the world in between.
inline std::vector<double> record(SceneWorld& world, int frames, const std::function<double()>& read) {
  std::vector<double> out{read()};
  for (int f = 0; f < frames; ++f) {
    world.step_frame(f);
    out.push_back(read());
  }
  return out;
}

/// The chassis centre's y at frames 0..frames of the vehicle in Box2D 2.4 with the same typed springs, and
/// the wall time of a whole run of `run_frames` frames, ms.
struct Box2DVehicle {
  ResponseFit heave;
  double run_ms = 0.0;
};
inline Box2DVehicle box2d_vehicle(const Scene& s, int heave_frames) {
  Box2DVehicle out;
  scene::Box2DScene box2d(s, s.mass_model);
  std::vector<double> y{box2d.bodies()[1]->GetWorldCenter().y};
  const int frames = scene::frame_count(s.world);
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    box2d.step_frame(f);
    if (f < heave_frames) y.push_back(box2d.bodies()[1]->GetWorldCenter().y);
  }
  out.run_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out.heave = fit_response(y, 1.0 / s.world.fps);
  return out;
}

inline int body_of(const Scene& s, const std::string& id) {
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (s.bodies[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

/// k, c for f Hz and damping ratio zeta on mass m (the continuous oscillator).
inline JointSpring spring_for(double m, double f, double zeta) {
  const double w = 2 * 3.14159265358979323846 * f;
  return {m * w * w, 2 * m * zeta * w};
}

/// The fit of `samples` against the engine's own 1-D step (`model`, within 1 % / 0.01) and against the
/// continuous oscillator it was tuned for (within `continuous_f` relative / `continuous_zeta`: the step's
/// integrator error).
inline void expect_response(const std::vector<double>& samples, double h, const engines::Prediction& model,
                            double f, double zeta, double continuous_f, double continuous_zeta) {
  const ResponseFit fit = fit_response(samples, h);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  ASSERT_TRUE(model.frequency_hz && model.damping_ratio);
  EXPECT_NEAR(*fit.frequency_hz / *model.frequency_hz, 1.0, 0.01);
  EXPECT_NEAR(*fit.damping_ratio, *model.damping_ratio, 0.01);
  EXPECT_NEAR(*fit.frequency_hz / f, 1.0, continuous_f);
  EXPECT_NEAR(*fit.damping_ratio, zeta, continuous_zeta);
}

inline bool all_finite(const SceneWorld& world, std::size_t bodies) {
  for (std::size_t i = 0; i < bodies; ++i) {
    const scene::BodyState b = world.body(i);
    if (!b.centre.allFinite() || !b.velocity.allFinite() || !std::isfinite(b.angle)) return false;
  }
  return true;
}

/// The vehicle run in one engine with both suspensions at k, c (the car lowered by `lower`): the chassis heave
/// over 0-2 s, the state when the motor starts (2 s) and at the end, and the run's wall time.
struct VehicleRun {
  bool built = false;
  bool finite = true;
  ResponseFit heave;
  double chassis_x_at_motor = 0.0, wheel_y_at_motor = 0.0;
  double chassis_x_end = 0.0, box_moved = 0.0;
  double run_ms = 0.0;
  Box2DVehicle box2d;
};
inline VehicleRun run_vehicle(const SceneBackend& backend, double k, double c, double lower = 0.0,
                              const engines::SettingValues& settings = {}) {
  VehicleRun out;
  const Scene s = typed_vehicle(k, c, lower);
  const int chassis = body_of(s, "chassis"), wheel = body_of(s, "rear_wheel"), box = body_of(s, "box_0_0");
  const int heave_frames = static_cast<int>(std::lround(2.0 * s.world.fps));
  std::optional<FieldError> error;
  auto world = build_scene(backend, s, Springs(2, JointSpring{k, c}), error, settings);
  if (!world) return out;
  out.built = true;
  std::vector<double> heave{world->body(chassis).centre.y()};
  const int frames = scene::frame_count(s.world);
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < frames; ++f) {
    world->step_frame(f);
    out.finite = out.finite && all_finite(*world, s.bodies.size());
    if (f < heave_frames) heave.push_back(world->body(chassis).centre.y());
    if (f + 1 == heave_frames) {
      out.chassis_x_at_motor = world->body(chassis).centre.x();
      out.wheel_y_at_motor = world->body(wheel).centre.y();
    }
  }
  out.run_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  out.chassis_x_end = world->body(chassis).centre.x();
  out.box_moved = world->body(box).centre.x() - s.bodies[static_cast<std::size_t>(box)].position.x();
  out.heave = fit_response(heave, 1.0 / s.world.fps);
  out.box2d = box2d_vehicle(typed_vehicle(k, c), heave_frames);  // Box2D from the preset's start, on its skin
  return out;
}

inline void print_vehicle(std::string_view engine, const VehicleRun& v) {
  std::printf("%.*s vehicle heave: %.3f Hz zeta %.3f (Box2D 2.4, same k, c: %.3f Hz zeta %.3f); 6 s run %.1f ms "
              "(Box2D 2.4 %.1f ms, ratio %.2f)\n",
              static_cast<int>(engine.size()), engine.data(), v.heave.frequency_hz.value_or(0),
              v.heave.damping_ratio.value_or(0), v.box2d.heave.frequency_hz.value_or(0),
              v.box2d.heave.damping_ratio.value_or(0), v.run_ms, v.box2d.run_ms, v.run_ms / v.box2d.run_ms);
}

/// Every preset in one engine: built and run its whole duration finite, or refused naming a scene feature
/// and the engine.
inline void expect_presets_run_or_refused(const SceneBackend& backend) {
  for (const std::string& name : preset_names()) {
    SCOPED_TRACE(name);
    const Scene s = load_preset(name);
    std::optional<FieldError> error;
    auto world = build_scene(backend, s, box2d_springs(s), error);
    if (!world) {
      ASSERT_TRUE(error);
      EXPECT_TRUE(error->field.rfind("joints.", 0) == 0 || error->field.rfind("bodies.", 0) == 0) << error->field;
      EXPECT_NE(error->rule.find(backend.name), std::string::npos) << error->rule;
      std::printf("%s %s: refused, %s: %s\n", backend.name.data(), name.c_str(), error->field.c_str(),
                  error->rule.c_str());
      continue;
    }
    const int frames = scene::frame_count(s.world);
    bool finite = true;
    for (int f = 0; f < frames; ++f) {
      world->step_frame(f);
      finite = finite && all_finite(*world, s.bodies.size());
    }
    EXPECT_TRUE(finite);
    std::printf("%s %s: ran %d frames, finite %d\n", backend.name.data(), name.c_str(), frames, finite ? 1 : 0);
  }
}

/// The triangle's rest in one engine after 2 s: on its base (within the engine's contact skin, 2 cm), flat,
/// still, its centre of mass the centroid above its origin.
inline void expect_triangle_rests(const SceneBackend& backend) {
  const Scene s = dropped_triangle();
  std::optional<FieldError> error;
  auto world = build_scene(backend, s, {}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  record(*world, 120, [] { return 0.0; });
  const scene::BodyState b = world->body(1);
  EXPECT_NEAR(b.origin.y(), 0.0, 0.02);
  EXPECT_NEAR(b.origin.x(), 0.0, 0.01);
  EXPECT_NEAR(b.angle, 0.0, 0.01);
  EXPECT_LT(b.velocity.norm(), 0.01);
  EXPECT_NEAR((b.centre - b.origin - Eigen::Rotation2Dd(b.angle) * Eigen::Vector2d(0, 0.2)).norm(), 0.0, 1e-5);
}


/// A box (friction 0.4) sliding at 3 m/s on a ground box (friction 0.9): Box2D's mixed friction
/// sqrt(0.4 0.9) = 0.6 decelerates it at 0.6 g = 6 m/s^2, so after 0.25 s it moves at 1.5 m/s and stops at
/// 0.5 s, 0.75 m on.
inline void expect_friction_mixes_as_box2d(const SceneBackend& backend) {
  Scene s;
  s.name = "sliding_box";
  s.bodies.push_back(box_body("ground", {0, -0.5}, 20.0, 1.0, true));
  s.bodies[0].friction = 0.9;
  BodySettings b = box_body("box", {0, 0.25}, 0.5, 0.5, false, 2.0);
  b.friction = 0.4;
  b.linear_velocity = {3.0, 0};
  s.bodies.push_back(b);
  std::optional<FieldError> error;
  auto world = build_scene(backend, s, {}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  const std::vector<double> vx = record(*world, 60, [&] { return world->body(1).velocity.x(); });
  EXPECT_NEAR(vx[15], 1.5, 0.1);
  EXPECT_NEAR(vx[60], 0.0, 0.02);
  EXPECT_NEAR(world->body(1).centre.x(), 0.75, 0.06);
}

}  // namespace softtune::test_support::scene_cases
