// Scenes in Bullet 3.24 (engines/bullet/bullet_scene.h), against the physics: one body on one soft joint
// measured against Bullet's own 1-D step (core/engines/bullet.h: the spring2 row is semi-implicit Euler on
// (m, k, c) with k, c as typed when limitIfNeeded is false) and the continuous oscillator, the vehicle next to
// Box2D 2.4 with the same k, c, every preset, a refusal, and the fields' round trip.
#include "bullet_scene.h"

#include <gtest/gtest.h>

#include "../scene_backend_cases.h"
#include "softtune/engines/bullet.h"

namespace softtune::scene {
namespace {

using namespace test_support::scene_cases;

engines::Prediction bullet_scene_model(double m, const JointSpring& s, double h) {
  return engines::predict_from_step_map(engines::bullet_spring2_step_map(m, s.stiffness, s.damping, h), h);
}

TEST(BulletScene, HangingBoxOnADistanceSpringBobsAtBulletsSpringFrequency) {
  const Scene s = hanging_box();
  const JointSpring spring = spring_for(2.0, 2.0, 0.1);
  std::optional<FieldError> error;
  auto world = build_scene(kBulletSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  const std::vector<double> y = record(*world, 180, [&] { return world->body(1).centre.y(); });
  // Semi-implicit Euler at omega h = 0.21: a few percent from the continuous oscillator.
  expect_response(y, 1.0 / 60, bullet_scene_model(2.0, spring, 1.0 / 60), 2.0, 0.1, 0.05, 0.05);
  EXPECT_NEAR(world->body(1).centre.x(), 0.0, 1e-4);  // it hangs straight
  EXPECT_NEAR(world->body(1).angle, 0.0, 1e-4);
}

TEST(BulletScene, WheelSliderSpringsAlongTheAxisHoldsAcrossItAndSpinsFree) {
  const Scene s = wheel_slider();
  const JointSpring spring = spring_for(3.0, 1.5, 0.2);
  std::optional<FieldError> error;
  auto world = build_scene(kBulletSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  double drift = 0.0;
  const std::vector<double> x = record(*world, 240, [&] {
    drift = std::max(drift, std::abs(world->body(1).centre.y()));
    return world->body(1).centre.x();
  });
  expect_response(x, 1.0 / 60, bullet_scene_model(3.0, spring, 1.0 / 60), 1.5, 0.2, 0.05, 0.05);
  EXPECT_LT(drift, 1e-3);
  EXPECT_NEAR(world->body(1).angular_velocity, 1.0, 1e-3);  // free rotation: still its starting 1 rad/s
}

TEST(BulletScene, WeldedBoxSwingsOnTheWeldsSoftRotation) {
  const Scene s = welded_box();
  const JointSpring spring = spring_for(kWeldedBoxInertia, 1.0, 0.1);  // N m/rad, N m s/rad
  std::optional<FieldError> error;
  auto world = build_scene(kBulletSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  double drift = 0.0;
  const std::vector<double> angle = record(*world, 240, [&] {
    drift = std::max(drift, world->body(1).centre.norm());
    return world->body(1).angle;
  });
  expect_response(angle, 1.0 / 60, bullet_scene_model(kWeldedBoxInertia, spring, 1.0 / 60), 1.0, 0.1, 0.05, 0.05);
  EXPECT_LT(drift, 1e-3);  // the weld holds its translation
}

TEST(BulletScene, MouseSpringPullsTheBoxToItsTarget) {
  const Scene s = mouse_box();
  const JointSpring spring = spring_for(1.5, 2.0, 0.3);
  std::optional<FieldError> error;
  auto world = build_scene(kBulletSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  const std::vector<double> x = record(*world, 180, [&] { return world->body(0).centre.x(); });
  expect_response(x, 1.0 / 60, bullet_scene_model(1.5, spring, 1.0 / 60), 2.0, 0.3, 0.05, 0.05);
  EXPECT_NEAR(world->body(0).centre.x(), 0.3, 1e-3);
  EXPECT_NEAR(world->body(0).centre.y(), 1.0, 1e-6);
}

TEST(BulletScene, ADroppedPolygonPrismLandsFlatOnItsBase) { expect_triangle_rests(kBulletSceneBackend); }

TEST(BulletScene, FrictionMixesAsBox2DsSqrtOfTheProduct) { expect_friction_mixes_as_box2d(kBulletSceneBackend); }

TEST(BulletScene, VehicleSettlesHeavesNearThreeHertzAndDrivesIntoTheBoxes) {
  // As the preset is (the tyres 5 mm above the road: the landing is in the heave), then on the road.
  const VehicleRun preset = run_vehicle(kBulletSceneBackend, kVehicleStiffness, kVehicleDamping);
  print_vehicle("bullet (preset start)", preset);
  const VehicleRun v = run_vehicle(kBulletSceneBackend, kVehicleStiffness, kVehicleDamping, kBox2DTyreLift);
  ASSERT_TRUE(v.built && preset.built);
  ASSERT_TRUE(v.finite && preset.finite);
  print_vehicle("bullet (tyres on the road)", v);
  EXPECT_NEAR(v.wheel_y_at_motor, 0.4, 0.02);  // settled: the tyres on the road
  EXPECT_NEAR(v.chassis_x_at_motor, 0.0, 0.05);
  ASSERT_TRUE(v.heave.frequency_hz && v.heave.damping_ratio);
  // Box2D 2.4's implicit soft step gives 3 Hz, zeta 0.5 with these k, c; Bullet's explicit spring row gives
  // its own step's answer: the quarter car (half the chassis, 60 kg, on one spring, the wheel held by the
  // road) in semi-implicit Euler is 3.50 Hz, zeta 0.40 -- the explicit damping (c h / m = 0.25) raises the
  // natural frequency.
  const engines::Prediction quarter_car = bullet_scene_model(60.0, {kVehicleStiffness, kVehicleDamping}, 1.0 / 60);
  ASSERT_TRUE(quarter_car.frequency_hz && quarter_car.damping_ratio);
  EXPECT_NEAR(*v.heave.frequency_hz / *quarter_car.frequency_hz, 1.0, 0.03);
  EXPECT_NEAR(*v.heave.damping_ratio, *quarter_car.damping_ratio, 0.03);
  EXPECT_GT(v.chassis_x_end - v.chassis_x_at_motor, 5.0);  // the motor drives it right, into the stack
  EXPECT_GT(v.box_moved, 0.1);
  EXPECT_GT(preset.chassis_x_end - preset.chassis_x_at_motor, 5.0);
}

TEST(BulletScene, EveryPresetRunsItsWholeDurationFiniteOrIsRefusedNamingAFeature) {
  expect_presets_run_or_refused(kBulletSceneBackend);
}

TEST(BulletScene, ACappedMouseIsRefusedNamingItsMaxForceAndBullet) {
  Scene s = load_preset("mouse");
  s.joints[0].max_force = 500.0;
  std::optional<FieldError> error;
  EXPECT_FALSE(build_scene(kBulletSceneBackend, s, box2d_springs(s), error));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "joints.0.max_force");
  EXPECT_NE(error->rule.find("bullet"), std::string::npos);
}

TEST(BulletScene, FieldsParseBackToTheSpringAndAMissingFieldIsNamed) {
  const Scene s = wheel_slider();
  const JointSpring spring{1234.5, 67.25};  // both exact in float
  const engines::Parameters typed = kBulletSceneBackend.fields(s, 0, spring, {});
  FieldError error;
  const std::optional<JointSpring> back = kBulletSceneBackend.parse(s, 0, typed, {}, error);
  ASSERT_TRUE(back);
  EXPECT_DOUBLE_EQ(back->stiffness, spring.stiffness);
  EXPECT_DOUBLE_EQ(back->damping, spring.damping);
  engines::Parameters missing;
  for (const engines::Parameter& p : typed) {
    if (p.name != engines::kBulletDamping) missing.push_back(p);
  }
  EXPECT_FALSE(kBulletSceneBackend.parse(s, 0, missing, {}, error));
  EXPECT_EQ(error.field, engines::kBulletDamping);
}

}  // namespace
}  // namespace softtune::scene
