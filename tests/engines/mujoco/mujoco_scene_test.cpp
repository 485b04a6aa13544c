// The MuJoCo 2.2.2 scene backend (engines/mujoco/mujoco_scene.h) in the real engine: one body on one soft joint
// measured against the analytic oscillator and against MuJoCo's own integrator (semi-implicit Euler, joint
// damping implicit in mj_Euler), the vehicle on Box2D's suspension k, c (heave, drive, push), every preset built
// and run (or refused naming a feature), the refusals, and the fields a designer types read back.
#include "mujoco_scene.h"

#include <gtest/gtest.h>

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>

#include <cstring>
#include <memory>
#include <cmath>
#include <numbers>

#include "softtune/designer.h"
#include "softtune/engines/engine_model.h"
#include "softtune/engines/mujoco.h"
#include "softtune/response_fit.h"
#include "softtune/scene/runner.h"
#include "softtune/scene/scene_geometry.h"
#include "../scene_backend_cases.h"

namespace softtune::engines {
namespace {

using scene::BodySettings;
using scene::JointKind;
using scene::JointSettings;
using scene::JointSpring;
using scene::Scene;
using scene::SceneBuild;

using test_support::scene_cases::load_preset;

BodySettings mjscene_box(const std::string& id, Eigen::Vector2d at, double mass, bool is_static = false) {
  BodySettings b;
  b.id = id;
  b.position = at;
  b.is_static = is_static;
  b.shape.width = b.shape.height = 0.5;
  if (!is_static) b.mass = mass;
  return b;
}

// The springs Box2D 2.4 needs for the vehicle's 3 Hz, zeta 0.5 heave (the modal solve at 60 fps).
constexpr JointSpring kMjsceneSuspension{test_support::scene_cases::kVehicleStiffness,
                                         test_support::scene_cases::kVehicleDamping};

struct MjsceneRun {
  std::vector<scene::BodyState> states;  // body `probe` at every frame, frame 0 first
};

// Builds `s` in MuJoCo with these springs and records body `probe` for `frames` frames.
MjsceneRun mjscene_run(const Scene& s, std::vector<std::optional<JointSpring>> springs, std::size_t probe, int frames,
                       const SettingValues& settings = {}) {
  SceneBuild b{&s, std::move(springs), settings};
  std::optional<FieldError> error;
  auto world = kMujocoSceneBackend.build(b, error);
  EXPECT_TRUE(world) << (error ? error->field + ": " + error->rule : "");
  MjsceneRun run;
  if (!world) return run;
  run.states.push_back(world->body(probe));
  for (int f = 0; f < frames; ++f) {
    world->step_frame(f);
    run.states.push_back(world->body(probe));
  }
  return run;
}

// A static body at `fixed` and a dynamic box of `mass` at `moving` joined by one joint of `kind` (anchors at the
// bodies' centres; a mouse joint has no body_a).
Scene mjscene_pair(JointKind kind, Eigen::Vector2d fixed, Eigen::Vector2d moving, double mass) {
  Scene s;
  s.world.fps = 60;
  s.bodies = {mjscene_box("fixed", fixed, 0, true), mjscene_box("moving", moving, mass)};
  JointSettings j;
  j.id = "joint";
  j.kind = kind;
  j.body_a = kind == JointKind::mouse ? "" : "fixed";
  j.body_b = "moving";
  j.anchor_a = kind == JointKind::weld ? moving : fixed;
  j.anchor_b = moving;
  s.joints = {j};
  return s;
}

// mj_Euler's step of one coordinate whose spring (kappa = k / m) is applied explicitly and whose damping
// (beta = c / m, a joint's dof_damping) implicitly: (1 + h beta) v1 = v0 - h kappa r0, r1 = r0 + h v1.
Prediction mjscene_implicit_damping(double beta, double kappa, double h) {
  const double g = 1.0 / (1.0 + h * beta);
  Eigen::Matrix2d step;
  step << 1.0 - h * h * kappa * g, h * g, -h * kappa * g, g;
  return predict_from_step_map(step, h);
}

// A joint's fitted response against mj_Euler's step of it (to 1e-4) and the continuous oscillator (3 %, 0.03).
void mjscene_expect_implicit_damping(const ResponseFit& fit, const JointSpring& spring, double mass, double h,
                                     double frequency_hz, double zeta) {
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  const Prediction model = mjscene_implicit_damping(spring.damping / mass, spring.stiffness / mass, h);
  EXPECT_NEAR(*fit.frequency_hz, *model.frequency_hz, 1e-4 * frequency_hz);
  EXPECT_NEAR(*fit.damping_ratio, *model.damping_ratio, 1e-4);
  EXPECT_NEAR(*fit.frequency_hz, frequency_hz, 0.03 * frequency_hz);
  EXPECT_NEAR(*fit.damping_ratio, zeta, 0.03);
}

std::vector<double> mjscene_y(const MjsceneRun& r) {
  std::vector<double> y;
  for (const auto& st : r.states) y.push_back(st.centre.y());
  return y;
}

// A box of 2 kg hanging from a static box on a distance spring (k, c along the anchor line, rest = the start).
TEST(MujocoScene, DistanceSpringIsTheOscillatorOfItsKAndC) {
  const Scene s = mjscene_pair(JointKind::distance, {0, 5}, {0, 3}, 2.0);
  const double m = 2.0, omega = 2 * std::numbers::pi * 3.0, zeta = 0.2;
  const JointSpring spring{m * omega * omega, 2 * m * zeta * omega};
  const double h = 1.0 / 60;
  const MjsceneRun run = mjscene_run(s, {spring}, 1, 120);
  const ResponseFit fit = fit_response(mjscene_y(run), h);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  // MuJoCo's own step: the tendon's passive spring and damping applied explicitly, semi-implicit Euler
  // (mujoco_step_map, core/src/engines/mujoco.cpp) -- the discrete poles to round-off.
  const Prediction model = predict_from_step_map(mujoco_step_map(MujocoIntegrator::euler, spring.damping / m, spring.stiffness / m, h), h);
  EXPECT_NEAR(*fit.frequency_hz, *model.frequency_hz, 1e-4 * 3.0);
  EXPECT_NEAR(*fit.damping_ratio, *model.damping_ratio, 1e-4);
  // The continuous oscillator within the integrator's error at omega h = 0.31 (semi-implicit Euler with the
  // damping explicit: +3.8 % in frequency at zeta 0.2).
  EXPECT_NEAR(*fit.frequency_hz, 3.0, 0.05 * 3.0);
  EXPECT_NEAR(*fit.damping_ratio, zeta, 0.03);
  // The equilibrium: the rest length plus m g / k below the ceiling.
  EXPECT_NEAR(*fit.equilibrium, 3.0 - m * 10.0 / spring.stiffness, 1e-6);
}

// The integrator setting is MuJoCo's: RK4 steps the tendon spring as classic RK4 (mujoco_step_map), implicit
// takes the tendon damping into the velocity derivative as mj_Euler does a joint's.
TEST(MujocoScene, IntegratorSettingIsMujocosOwn) {
  const Scene s = mjscene_pair(JointKind::distance, {0, 5}, {0, 3}, 2.0);
  const double m = 2.0, omega = 2 * std::numbers::pi * 3.0, zeta = 0.2, h = 1.0 / 60;
  const JointSpring spring{m * omega * omega, 2 * m * zeta * omega};
  for (int integrator : {1, 2}) {
    SettingValues settings;
    for (const SettingSpec& spec : kMujocoSceneBackend.settings) settings.push_back(spec.default_value);
    settings[kMujocoSceneIntegrator] = integrator;
    const ResponseFit fit = fit_response(mjscene_y(mjscene_run(s, {spring}, 1, 120, settings)), h);
    ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
    const Prediction model =
        integrator == 1 ? predict_from_step_map(mujoco_step_map(MujocoIntegrator::rk4, spring.damping / m, spring.stiffness / m, h), h)
                        : mjscene_implicit_damping(spring.damping / m, spring.stiffness / m, h);
    EXPECT_NEAR(*fit.frequency_hz, *model.frequency_hz, 1e-4 * 3.0) << integrator;
    EXPECT_NEAR(*fit.damping_ratio, *model.damping_ratio, 1e-4) << integrator;
  }
}

// A box on a wheel joint to a static rail, axis up: the slide's passive spring is exact k, c; MuJoCo's Euler
// applies the joint damping implicitly: (1 + h b) v1 = v0 - h kappa r0, r1 = r0 + h v1 (b = c / m).
TEST(MujocoScene, WheelSpringIsTheOscillatorOfItsKAndCAndRigidAcross) {
  Scene s = mjscene_pair(JointKind::wheel, {0, 0}, {1, 0}, 3.0);
  s.joints[0].axis = {0, 1};
  const double m = 3.0, omega = 2 * std::numbers::pi * 2.0, zeta = 0.3, h = 1.0 / 60;
  const JointSpring spring{m * omega * omega, 2 * m * zeta * omega};
  const MjsceneRun run = mjscene_run(s, {spring}, 1, 120);
  const ResponseFit fit = fit_response(mjscene_y(run), h);
  mjscene_expect_implicit_damping(fit, spring, m, h, 2.0, zeta);
  EXPECT_NEAR(*fit.equilibrium, -m * 10.0 / spring.stiffness, 1e-6);
  for (const auto& st : run.states) EXPECT_NEAR(st.centre.x(), 1.0, 1e-9);  // rigid across the axis
}

// A soft weld: body_b turns on a hinge at the anchor (its centre) with the spring in N m/rad on its inertia.
TEST(MujocoScene, SoftWeldIsTheAngularOscillatorOfItsKAndC) {
  Scene s = mjscene_pair(JointKind::weld, {0, 0}, {1, 0}, 2.0);
  s.world.gravity = {0, 0};
  s.bodies[1].angular_velocity = 1.0;
  const double inertia = 2.0 * (0.25 + 0.25) / 12, omega = 2 * std::numbers::pi * 2.0, zeta = 0.1, h = 1.0 / 60;
  const JointSpring spring{inertia * omega * omega, 2 * inertia * zeta * omega};
  const MjsceneRun run = mjscene_run(s, {spring}, 1, 120);
  std::vector<double> angle;
  for (const auto& st : run.states) angle.push_back(st.angle);
  const ResponseFit fit = fit_response(angle, h);
  mjscene_expect_implicit_damping(fit, spring, inertia, h, 2.0, zeta);
  for (const auto& st : run.states) EXPECT_NEAR((st.centre - Eigen::Vector2d(1, 0)).norm(), 0.0, 1e-9);
}

// A rigid distance rod (no spring) holds its rest length, the starting distance or `length`, as a pendulum
// swings under gravity: MuJoCo's tendon equality is soft (solref 0.02 1 raised to 2 timestep), so within 2 cm.
TEST(MujocoScene, RigidRodHoldsItsRestLength) {
  for (double length : {1.0, 1.2}) {
    Scene s = mjscene_pair(JointKind::distance, {0, 5}, {1, 5}, 1.0);
    s.joints[0].length = length;
    const MjsceneRun run = mjscene_run(s, {std::nullopt}, 1, 120);
    double lowest = 5.0;
    for (std::size_t f = 30; f < run.states.size(); ++f) {
      EXPECT_NEAR((run.states[f].centre - Eigen::Vector2d(0, 5)).norm(), length, 0.02) << f;
      lowest = std::min(lowest, run.states[f].centre.y());
    }
    EXPECT_LT(lowest, 5.0 - 0.9 * length);  // it swung down
  }
}

// A mouse joint's pull is capped at max_force like b2MouseJoint's: a 1 kg box 1 m from its target on a
// 100 N/m spring capped at 5 N accelerates at 5 m/s^2, not 100.
TEST(MujocoScene, MousePullIsCappedAtMaxForce) {
  Scene s = mjscene_pair(JointKind::mouse, {0, 3}, {0, 0}, 1.0);
  s.world.gravity = {0, 0};
  s.joints[0].target = {1, 0};
  s.joints[0].max_force = 5.0;
  const MjsceneRun run = mjscene_run(s, {JointSpring{100.0, 1.0}}, 1, 12);
  EXPECT_NEAR(run.states.back().velocity.x(), 5.0 * 12 / 60.0, 1e-6);
  EXPECT_NEAR(run.states.back().velocity.y(), 0.0, 1e-9);
}

// Box2D's friction mix sqrt(fa fb), not MuJoCo's max: a crate (0.6) on a road (0.9) tilted 40 degrees slides
// down at g (sin 40 - sqrt(0.54) cos 40) = 0.80 m/s^2; with the max (0.9 > tan 40 = 0.84) it would stick. (A
// crate launched fast along a flat road would not do: MuJoCo's soft friction at a 3 m/s slip pushes the
// crate off the road in one step.)
TEST(MujocoScene, FrictionMixesAsBox2DsSquareRoot) {
  const double tilt = 40.0 * std::numbers::pi / 180.0;
  const Eigen::Vector2d normal(-std::sin(tilt), std::cos(tilt)), down(-std::cos(tilt), -std::sin(tilt));
  Scene s;
  s.world.fps = 60;
  s.bodies = {mjscene_box("road", {0, 0}, 0, true), mjscene_box("crate", 0.75 * normal, 4.0)};
  s.bodies[0].shape.width = 40;
  s.bodies[0].shape.height = 1;
  s.bodies[0].friction = 0.9;
  s.bodies[0].angle = s.bodies[1].angle = tilt;
  s.bodies[1].friction = 0.6;
  const MjsceneRun run = mjscene_run(s, {}, 1, 60);
  auto along = [&](int f) { return (run.states[f].centre - s.bodies[1].position).dot(down); };
  // From 0.25 s (the contact has settled), three points 0.35 s apart: s2 - 2 s1 = a dt^2.
  const double dt = 0.35, s0 = along(15), s1 = along(36) - s0, s2 = along(57) - s0;
  const double accel = (s2 - 2.0 * s1) / (dt * dt);
  // The friction coefficient the slide shows: a = g (sin - mu cos). MuJoCo's friction is soft (a slip
  // velocity grows with the force), so it reads a little below the mix: 0.723 for 0.735.
  const double mu = (std::sin(tilt) - accel / 10.0) / std::cos(tilt);
  EXPECT_NEAR(mu, std::sqrt(0.6 * 0.9), 0.02);
}

// A polygon is a convex mesh prism where the scene puts it: a triangle whose centroid is off its origin rests
// with its bottom edge on the road (origin 0.2 m up), its centre of mass where body_mass() puts it.
TEST(MujocoScene, PolygonRestsWhereItsVerticesAre) {
  Scene s;
  s.world.fps = 60;
  s.bodies = {mjscene_box("road", {0, -0.5}, 0, true), mjscene_box("wedge", {0, 0.2}, 2.0)};
  s.bodies[0].shape.width = 10;
  s.bodies[0].shape.height = 1;
  s.bodies[1].shape.kind = scene::ShapeKind::polygon;
  s.bodies[1].shape.vertices = {{-0.5, -0.2}, {0.5, -0.2}, {0.3, 0.6}};
  const MjsceneRun run = mjscene_run(s, {}, 1, 60);
  const scene::BodyState& end = run.states.back();
  // Misplaced by MuJoCo's re-centring of the mesh it would be off by the centroid's 0.067 m. The soft contact
  // sinks it 7.5 mm, and a mesh meets the box in one contact point (libccd) at a time: it rocks by 1.4 mrad.
  EXPECT_NEAR(end.origin.y(), 0.2, 0.01);
  EXPECT_NEAR(end.angle, 0.0, 5e-3);
  const Eigen::Vector2d centre = end.origin + Eigen::Rotation2Dd(end.angle) * scene::body_mass(s.bodies[1]).local_centre;
  EXPECT_NEAR((end.centre - centre).norm(), 0.0, 1e-9);
}

// The MJCF a designer opens in MuJoCo holds the scene's numbers under the names the header gives: the
// suspension's slide joints carry k and c, the chassis its mass, the road-and-box pairs Box2D's friction.
TEST(MujocoScene, MjcfCarriesTheSpringsMassesAndFrictionPairs) {
  const Scene s = load_preset("vehicle");
  SceneBuild b{&s, {kMjsceneSuspension, kMjsceneSuspension}, {}};
  std::optional<FieldError> error;
  const std::string xml = mujoco_scene_mjcf(b, error);
  ASSERT_FALSE(error);
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  ASSERT_EQ(mj_makeEmptyFileVFS(vfs.get(), "vehicle.xml", static_cast<int>(xml.size())), 0);
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), "vehicle.xml")], xml.data(), xml.size());
  char message[1000] = "";
  mjModel* m = mj_loadXML("vehicle.xml", vfs.get(), message, sizeof(message));
  mj_deleteVFS(vfs.get());
  ASSERT_TRUE(m) << message;
  for (const char* joint : {"rear_suspension", "front_suspension"}) {
    const int id = mj_name2id(m, mjOBJ_JOINT, joint);
    ASSERT_GE(id, 0) << joint;
    EXPECT_EQ(m->jnt_type[id], mjJNT_SLIDE);
    EXPECT_EQ(m->jnt_stiffness[id], kMjsceneSuspension.stiffness);
    EXPECT_EQ(m->dof_damping[m->jnt_dofadr[id]], kMjsceneSuspension.damping);
  }
  EXPECT_EQ(m->body_mass[mj_name2id(m, mjOBJ_BODY, "chassis")], 120.0);
  // 0.9 (road, two tyres) against 0.6 (chassis, twelve boxes), less the chassis-tyre pairs the joints exclude.
  EXPECT_EQ(m->npair, 3 * 13 - 2);
  EXPECT_NEAR(m->pair_friction[0], std::sqrt(0.9 * 0.6), 1e-12);
  EXPECT_EQ(m->nexclude, 2);
  mj_deleteModel(m);
}


// The vehicle on Box2D's suspension k, c from the preset's start: it settles on its wheels, heaves near 3 Hz, and
// from 2 s the motor drives it right into the stack. Not Box2D's 3.00 Hz / 0.50: these k, c are what Box2D's
// soft step needs (its implicit Euler adds about omega h / 2 of damping), MuJoCo steps the springs
// semi-implicitly (joint damping implicit), and its tyres have no skin: the car starts 5 mm up and lands (the
// next test). Measured: 2.968 Hz, zeta 0.273.
TEST(MujocoScene, VehicleSettlesHeavesNearThreeHertzAndDrivesIntoTheBoxes) {
  using namespace test_support::scene_cases;
  const VehicleRun v = run_vehicle(kMujocoSceneBackend, kVehicleStiffness, kVehicleDamping);
  ASSERT_TRUE(v.built);
  print_vehicle("mujoco", v);
  EXPECT_TRUE(v.finite);
  ASSERT_TRUE(v.heave.frequency_hz && v.heave.damping_ratio && v.heave.equilibrium);
  EXPECT_NEAR(*v.heave.equilibrium, 1.005 - 0.005 - 120.0 * 10.0 / (2 * kVehicleStiffness), 0.005);  // sag on 2 k
  EXPECT_NEAR(*v.heave.frequency_hz, 3.0, 0.1 * 3.0);
  EXPECT_GT(*v.heave.damping_ratio, 0.15);
  EXPECT_LT(*v.heave.damping_ratio, 0.6);
  EXPECT_NEAR(v.chassis_x_at_motor, 0.0, 0.05);  // parked until the motor starts
  EXPECT_GT(v.chassis_x_end, 5.0);
  EXPECT_GT(v.box_moved, 0.05);
}

// The heave MuJoCo converges to is the continuous chassis on its two springs over rigid tyres,
// omega^2 = 2 k / M, zeta = 2 c / (2 sqrt(2 k M)) (3.239 Hz, 0.375; Box2D at 32 substeps: 3.232 Hz, 0.379), with
// the tyres touching at the start (the preset's 5 mm of Box2D contact skin taken out: with it the landing's
// bounce makes the fit read 3.43 Hz, 0.35) and at 32 substeps, where the step's own error is gone.
TEST(MujocoScene, VehicleHeaveAtFineStepsIsTheContinuousChassisOnItsSprings) {
  using namespace test_support::scene_cases;
  Scene s = typed_vehicle(kVehicleStiffness, kVehicleDamping, kBox2DTyreLift);
  s.world.substeps = 32;
  const MjsceneRun run = mjscene_run(s, {kMjsceneSuspension, kMjsceneSuspension}, body_of(s, "chassis"), 120);
  const ResponseFit fit = fit_response(mjscene_y(run), 1.0 / s.world.fps);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  const double k = 2 * kMjsceneSuspension.stiffness, c = 2 * kMjsceneSuspension.damping, mass = 120.0;
  EXPECT_NEAR(*fit.frequency_hz, std::sqrt(k / mass) / (2 * std::numbers::pi), 0.015 * 3.24);
  EXPECT_NEAR(*fit.damping_ratio, c / (2 * std::sqrt(k * mass)), 0.01);
  EXPECT_LT(*fit.residual, 1e-3);  // one clean mode
}

// Revolute pins are hinges of MuJoCo's tree, exactly rigid: the chain's anchors coincide to round-off after its
// whole swing; the bridge's pin to its right bank closes a loop and is an <equality><connect>, MuJoCo-soft (1.4 cm under the loaded bridge).
TEST(MujocoScene, RevolutePinsAreRigidHingesAndTheLoopClosingPinAConnect) {
  for (const char* name : {"chain", "bridge"}) {
    const Scene s = load_preset(name);
    SceneBuild b{&s, test_support::scene_cases::box2d_springs(s), {}};
    std::optional<FieldError> error;
    auto world = kMujocoSceneBackend.build(b, error);
    ASSERT_TRUE(world) << name;
    for (int f = 0; f < scene::frame_count(s.world); ++f) world->step_frame(f);
    double worst = 0.0, loop = 0.0;
    for (std::size_t i = 0; i < s.joints.size(); ++i) {
      const JointSettings& j = s.joints[i];
      if (j.kind != JointKind::revolute) continue;
      const auto a = static_cast<std::size_t>(test_support::scene_cases::body_of(s, j.body_a));
      const auto bb = static_cast<std::size_t>(test_support::scene_cases::body_of(s, j.body_b));
      // The anchor carried by each body from the start: rotate its offset from the body origin.
      auto carried = [&](std::size_t body) {
        const scene::BodyState st = world->body(body);
        const BodySettings& start = s.bodies[body];
        return Eigen::Vector2d(st.origin + Eigen::Rotation2Dd(st.angle - start.angle) * (j.anchor_a - start.position));
      };
      const double gap = (carried(a) - carried(bb)).norm();
      // A static body_b cannot be nested: the bridge's pin to its right bank is the connect.
      double& bound = s.bodies[bb].is_static ? loop : worst;
      bound = std::max(bound, gap);
    }
    std::printf("%s: nested pins' largest gap %.2e m, the loop-closing connect's %.2e m\n", name, worst, loop);
    EXPECT_LT(worst, 1e-9) << name;
    EXPECT_LT(loop, 0.03) << name;  // 1.4 cm at the end of the bridge run: solref 0.02 raised to 2 timestep
  }
}

// Each preset with Box2D's own tuning of its joints: built and run finite for its whole duration, or refused
// naming the feature and the engine. `stiff` is refused: its 20 Hz spring at 60 fps (omega h = 2.1) would blow
// up on MuJoCo's explicit passive spring, as the preset shows semi-implicit Euler does.
TEST(MujocoScene, EveryPresetRunsFiniteOrIsRefusedNamingTheFeature) {
  test_support::scene_cases::expect_presets_run_or_refused(kMujocoSceneBackend);
  const Scene s = load_preset("stiff");
  std::optional<FieldError> error;
  EXPECT_FALSE(test_support::scene_cases::build_scene(kMujocoSceneBackend, s, test_support::scene_cases::box2d_springs(s), error));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "joints.0");
}

// The runner (scene/runner.h) runs the vehicle preset in MuJoCo through the backend: the answer names the
// engine and gives the suspension's fields under MuJoCo's names; the wheels stay on their axes exactly (a
// slide joint of MuJoCo's tree: the runner's constraint error from the poses is round-off).
TEST(MujocoScene, RunnerRunsThePresetInMujoco) {
  const Scene s = load_preset("vehicle");
  scene::RunOptions options;
  options.backend = &kMujocoSceneBackend;
  const scene::SceneResult r = scene::run_scene(s, options);
  ASSERT_FALSE(r.error) << r.error->field << ": " << r.error->rule;
  EXPECT_EQ(r.engine, "mujoco");
  EXPECT_EQ(r.engine_version, "MuJoCo 2.2.2");
  EXPECT_TRUE(r.finite);
  EXPECT_TRUE(r.left_world.empty());
  ASSERT_EQ(r.joint_fields.size(), 2u);
  ASSERT_FALSE(r.joint_fields[0].empty());
  EXPECT_EQ(r.joint_fields[0][0].name, "joint(slide)/@stiffness");
  EXPECT_GT(r.joint_fields[0][0].value, 0.0);
  EXPECT_LT(r.max_constraint_error, 1e-9);
  for (const scene::ProbeResult& p : r.probes) {
    if (p.id == "heave" && p.measured.frequency_hz && p.measured.damping_ratio) {
      std::printf("runner, vehicle in mujoco: heave %.3f Hz zeta %.3f, max constraint error %.2e m\n",
                  *p.measured.frequency_hz, *p.measured.damping_ratio, r.max_constraint_error);
    }
  }
}

TEST(MujocoScene, RefusesWhatMujocoCannotRepresentNamingTheFieldAndEngine) {
  Scene s = load_preset("vehicle");
  s.bodies[4].restitution = 0.5;
  SceneBuild b{&s, {kMjsceneSuspension, kMjsceneSuspension}, {}};
  std::optional<FieldError> error;
  EXPECT_FALSE(kMujocoSceneBackend.build(b, error));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "bodies.4.restitution");
  EXPECT_NE(error->rule.find("mujoco"), std::string::npos) << error->rule;

  // A wheel cannot nest a body another wheel already nests (MuJoCo's tree has one parent per body).
  Scene twice = load_preset("vehicle");
  twice.joints[1].body_b = twice.joints[0].body_b;
  twice.joints[1].anchor_b = twice.joints[0].anchor_b;
  SceneBuild b2{&twice, {kMjsceneSuspension, kMjsceneSuspension}, {}};
  error.reset();
  EXPECT_FALSE(kMujocoSceneBackend.build(b2, error));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "joints.1.body_b");
  EXPECT_NE(error->rule.find("mujoco"), std::string::npos) << error->rule;
  EXPECT_FALSE(mujoco_scene_mjcf(b2, error).size());
}

TEST(MujocoScene, TypedFieldsReadBackAndAMissingOneIsNamed) {
  Scene s;
  s.bodies = {mjscene_box("a", {0, 0}, 0, true), mjscene_box("b", {0, -1}, 1.0)};
  for (JointKind kind : {JointKind::distance, JointKind::wheel, JointKind::weld, JointKind::mouse}) {
    JointSettings j;
    j.id = "j";
    j.kind = kind;
    j.body_a = kind == JointKind::mouse ? "" : "a";
    j.body_b = "b";
    j.anchor_b = {0, -1};
    s.joints = {j};
    const JointSpring spring{1234.5, 67.25};
    const Parameters typed = kMujocoSceneBackend.fields(s, 0, spring, {});
    ASSERT_GE(typed.size(), 2u);
    FieldError error;
    const std::optional<JointSpring> back = kMujocoSceneBackend.parse(s, 0, typed, {}, error);
    ASSERT_TRUE(back) << error.field << ": " << error.rule;
    EXPECT_EQ(back->stiffness, spring.stiffness);
    EXPECT_EQ(back->damping, spring.damping);
    const Parameters missing(typed.begin() + 1, typed.end());
    EXPECT_FALSE(kMujocoSceneBackend.parse(s, 0, missing, {}, error));
    EXPECT_EQ(error.field, std::string(typed[0].name));
    EXPECT_NE(error.rule.find("missing"), std::string::npos) << error.rule;
  }
}

}  // namespace
}  // namespace softtune::engines
