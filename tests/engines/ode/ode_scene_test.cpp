// Scenes in ODE 0.16 (engines/ode/ode_scene.h), against the physics: one body on one soft joint measured
// against ODE's own 1-D step (core/engines/ode.h: ERP, CFM on one row are implicit Euler on k, c with
// dWorldStep) and the continuous oscillator, the vehicle next to Box2D 2.4 with the same k, c, every preset,
// refusals, and the fields' round trip.
#include "ode_scene.h"

#include <gtest/gtest.h>

#include "../scene_backend_cases.h"
#include "softtune/engines/ode.h"

namespace softtune::scene {
namespace {

using namespace test_support::scene_cases;

// ODE's 1-D step with the fields the backend types for this spring (dWorldStep: the impulse fraction 1).
engines::Prediction ode_scene_model(const Scene& s, double m, const JointSpring& spring, double h) {
  const engines::Parameters p = kOdeSceneBackend.fields(s, 0, spring, {});
  return engines::predict_from_step_map(engines::ode_step_map(m, p[0].value, p[1].value, h, 1.0), h);
}

TEST(OdeScene, HangingBoxOnADistanceSpringBobsAtOdesSpringFrequency) {
  const Scene s = hanging_box();
  const JointSpring spring = spring_for(2.0, 2.0, 0.1);
  std::optional<FieldError> error;
  auto world = build_scene(kOdeSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  const std::vector<double> y = record(*world, 180, [&] { return world->body(1).centre.y(); });
  // Implicit Euler at omega h = 0.21 damps by about h omega / 2 = 0.1 more than asked.
  expect_response(y, 1.0 / 60, ode_scene_model(s, 2.0, spring, 1.0 / 60), 2.0, 0.1, 0.05, 0.15);
  EXPECT_NEAR(world->body(1).centre.x(), 0.0, 1e-6);  // it hangs straight
  EXPECT_NEAR(world->body(1).angle, 0.0, 1e-6);
}

TEST(OdeScene, WheelSliderSpringsAlongTheAxisHoldsAcrossItAndSpinsFree) {
  const Scene s = wheel_slider();
  const JointSpring spring = spring_for(3.0, 1.5, 0.2);
  std::optional<FieldError> error;
  auto world = build_scene(kOdeSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  double drift = 0.0;
  const std::vector<double> x = record(*world, 240, [&] {
    drift = std::max(drift, std::abs(world->body(1).centre.y()));
    return world->body(1).centre.x();
  });
  expect_response(x, 1.0 / 60, ode_scene_model(s, 3.0, spring, 1.0 / 60), 1.5, 0.2, 0.05, 0.1);
  EXPECT_LT(drift, 1e-3);
  EXPECT_NEAR(world->body(1).angular_velocity, 1.0, 1e-3);  // free rotation: still its starting 1 rad/s
}

TEST(OdeScene, WeldedBoxSwingsOnTheWeldsSoftRotation) {
  const Scene s = welded_box();
  const JointSpring spring = spring_for(kWeldedBoxInertia, 1.0, 0.1);  // N m/rad, N m s/rad
  std::optional<FieldError> error;
  auto world = build_scene(kOdeSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  double drift = 0.0;
  const std::vector<double> angle = record(*world, 240, [&] {
    drift = std::max(drift, world->body(1).centre.norm());
    return world->body(1).angle;
  });
  expect_response(angle, 1.0 / 60, ode_scene_model(s, kWeldedBoxInertia, spring, 1.0 / 60), 1.0, 0.1, 0.05, 0.1);
  EXPECT_LT(drift, 1e-3);  // the weld holds its translation
}

TEST(OdeScene, MouseSpringPullsTheBoxToItsTarget) {
  const Scene s = mouse_box();
  const JointSpring spring = spring_for(1.5, 2.0, 0.3);
  std::optional<FieldError> error;
  auto world = build_scene(kOdeSceneBackend, s, {spring}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  const std::vector<double> x = record(*world, 180, [&] { return world->body(0).centre.x(); });
  expect_response(x, 1.0 / 60, ode_scene_model(s, 1.5, spring, 1.0 / 60), 2.0, 0.3, 0.05, 0.1);
  EXPECT_NEAR(world->body(0).centre.x(), 0.3, 1e-3);
  EXPECT_NEAR(world->body(0).centre.y(), 1.0, 1e-6);
}

TEST(OdeScene, FrictionMixesAsBox2DsSqrtOfTheProduct) { expect_friction_mixes_as_box2d(kOdeSceneBackend); }

TEST(OdeScene, VehicleSettlesHeavesAtThreeHertzAndDrivesIntoTheBoxes) {
  // As the preset is (the tyres 5 mm above the road: the landing is in the heave), then on the road.
  const VehicleRun preset = run_vehicle(kOdeSceneBackend, kVehicleStiffness, kVehicleDamping);
  print_vehicle("ode (preset start)", preset);
  const VehicleRun v = run_vehicle(kOdeSceneBackend, kVehicleStiffness, kVehicleDamping, kBox2DTyreLift);
  ASSERT_TRUE(v.built && preset.built);
  ASSERT_TRUE(v.finite && preset.finite);
  print_vehicle("ode (tyres on the road)", v);
  EXPECT_NEAR(v.wheel_y_at_motor, 0.4, 0.02);  // settled: the tyres on the road
  EXPECT_NEAR(v.chassis_x_at_motor, 0.0, 0.05);
  ASSERT_TRUE(v.heave.frequency_hz && v.heave.damping_ratio);
  // ODE's ERP / CFM row is implicit Euler on k, c, as Box2D 2.4's soft step: the quarter car (half the
  // chassis, 60 kg, on one spring, the wheel held by the road) in ODE's 1-D step is the 3 Hz, zeta 0.5 the
  // modal tuning solved these k, c for in Box2D.
  const engines::Prediction quarter_car = ode_scene_model(typed_vehicle(kVehicleStiffness, kVehicleDamping), 60.0,
                                                          {kVehicleStiffness, kVehicleDamping}, 1.0 / 60);
  ASSERT_TRUE(quarter_car.frequency_hz && quarter_car.damping_ratio);
  EXPECT_NEAR(*quarter_car.frequency_hz, 3.0, 0.01);
  EXPECT_NEAR(*v.heave.frequency_hz / *quarter_car.frequency_hz, 1.0, 0.02);
  EXPECT_NEAR(*v.heave.damping_ratio, *quarter_car.damping_ratio, 0.02);
  EXPECT_GT(v.chassis_x_end - v.chassis_x_at_motor, 5.0);  // the motor drives it right, into the stack
  EXPECT_GT(v.box_moved, 0.1);
  EXPECT_GT(preset.chassis_x_end - preset.chassis_x_at_motor, 5.0);
}

TEST(OdeScene, VehicleInQuickStepHeavesAtThreeHertzAndDrives) {
  // dWorldQuickStep (stepper 1) with ODE's 20 sweeps at w = 1.3: SOR from lambda = 0 reaches the rows'
  // exact impulses to 1 - (1 - w)^20 = 1 - 3.5e-11 (ode_impulse_fraction) -- the heave is dWorldStep's, in
  // about half its time.
  const VehicleRun v = run_vehicle(kOdeSceneBackend, kVehicleStiffness, kVehicleDamping, kBox2DTyreLift,
                                   {1, 20, 1.3, 0.2, 1e-10});
  ASSERT_TRUE(v.built && v.finite);
  print_vehicle("ode dWorldQuickStep (tyres on the road)", v);
  EXPECT_NEAR(v.wheel_y_at_motor, 0.4, 0.02);
  ASSERT_TRUE(v.heave.frequency_hz && v.heave.damping_ratio);
  EXPECT_NEAR(*v.heave.frequency_hz, 3.0, 0.06);
  EXPECT_NEAR(*v.heave.damping_ratio, 0.5, 0.02);
  EXPECT_GT(v.chassis_x_end - v.chassis_x_at_motor, 5.0);
}

TEST(OdeScene, EveryPresetRunsItsWholeDurationFiniteOrIsRefusedNamingAFeature) {
  expect_presets_run_or_refused(kOdeSceneBackend);
}

TEST(OdeScene, APolygonAndACappedMouseAreRefusedNamingTheFieldAndOde) {
  Scene s = hanging_box();
  s.bodies[1].shape.kind = ShapeKind::polygon;
  s.bodies[1].shape.vertices = {{-0.25, -0.25}, {0.25, -0.25}, {0.0, 0.25}};
  std::optional<FieldError> error;
  EXPECT_FALSE(build_scene(kOdeSceneBackend, s, {spring_for(2.0, 2.0, 0.1)}, error));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "bodies.1.shape.type");
  EXPECT_NE(error->rule.find("ode"), std::string::npos);

  Scene mouse = load_preset("mouse");
  mouse.joints[0].max_force = 500.0;
  error.reset();
  EXPECT_FALSE(build_scene(kOdeSceneBackend, mouse, box2d_springs(mouse), error));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "joints.0.max_force");
  EXPECT_NE(error->rule.find("ode"), std::string::npos);
}

TEST(OdeScene, FieldsParseBackToTheSpringAndAMissingFieldIsNamed) {
  for (const Scene& s : {hanging_box(), wheel_slider()}) {
    const JointSpring spring{1234.5, 67.25};
    const engines::Parameters typed = kOdeSceneBackend.fields(s, 0, spring, {});
    FieldError error;
    const std::optional<JointSpring> back = kOdeSceneBackend.parse(s, 0, typed, {}, error);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->stiffness / spring.stiffness, 1.0, 1e-12);
    EXPECT_NEAR(back->damping / spring.damping, 1.0, 1e-12);
    const engines::Parameters missing = {typed[0]};
    EXPECT_FALSE(kOdeSceneBackend.parse(s, 0, missing, {}, error));
    EXPECT_EQ(error.field, typed[1].name);
  }
  // The names: the dball's own ERP / CFM, the hinge-2's suspension.
  EXPECT_EQ(kOdeSceneBackend.fields(hanging_box(), 0, {1, 1}, {})[0].name, "dParamERP");
  EXPECT_EQ(kOdeSceneBackend.fields(wheel_slider(), 0, {1, 1}, {})[1].name, "dParamSuspensionCFM");
}

}  // namespace
}  // namespace softtune::scene
