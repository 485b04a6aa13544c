// The Jolt scene backend's C++ side (engines/jolt/jolt_scene.cpp): its settings and fields as Jolt spells
// them, parse(fields(k, c)) round trip, and -- where engines/jolt/jolt_scene.mjs is in the tree -- the
// vehicle preset at Box2D 2.4's 3 Hz / zeta 0.5 springs run in the real Jolt through the node worker.
#include "jolt_scene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "codec/scene_codec.h"
#include "softtune/response_fit.h"

namespace softtune::scene {
namespace {

constexpr JointSpring kJoltTestSpring{24842.07, 914.753};

engines::SettingValues jolt_test_defaults() {
  engines::SettingValues v;
  for (const engines::SettingSpec& s : kJoltSceneBackend.settings) v.push_back(s.default_value);
  return v;
}

Scene jolt_test_vehicle() {
  std::ifstream in(std::string(SOFTTUNE_SOURCE_DIR) + "/presets/vehicle.json");
  return codec::decode_scene(nlohmann::json::parse(in));
}

TEST(JoltScene, SettingsAreJoltsOwnWithItsDefaults) {
  ASSERT_EQ(kJoltSceneBackend.settings.size(), 2u);
  EXPECT_EQ(kJoltSceneBackend.settings[0].name, "PhysicsSettings::mNumVelocitySteps");
  EXPECT_EQ(kJoltSceneBackend.settings[0].default_value, 10);
  EXPECT_EQ(kJoltSceneBackend.settings[1].name, "PhysicsSettings::mNumPositionSteps");
  EXPECT_EQ(kJoltSceneBackend.settings[1].default_value, 2);
}

TEST(JoltScene, FieldsParseBackAndAMissingFieldIsNamed) {
  const Scene s = jolt_test_vehicle();
  const engines::Parameters typed = kJoltSceneBackend.fields(s, 0, kJoltTestSpring, jolt_test_defaults());
  ASSERT_EQ(typed.size(), 3u);
  EXPECT_EQ(typed[0].choice, "StiffnessAndDamping");
  FieldError error;
  const auto back = kJoltSceneBackend.parse(s, 0, typed, jolt_test_defaults(), error);
  ASSERT_TRUE(back) << error.field;
  EXPECT_EQ(back->stiffness, kJoltTestSpring.stiffness);
  EXPECT_EQ(back->damping, kJoltTestSpring.damping);
  EXPECT_FALSE(kJoltSceneBackend.parse(s, 0, {{"SpringSettings::mDamping", 1.0}}, jolt_test_defaults(), error));
  EXPECT_EQ(error.field, "SpringSettings::mStiffness");
}

TEST(JoltScene, VehicleHeavesNear3HzInTheRealJolt) {
  if (!std::filesystem::exists(std::string(SOFTTUNE_SOURCE_DIR) + "/engines/jolt/jolt_scene.mjs")) {
    GTEST_SKIP() << "engines/jolt/jolt_scene.mjs is not in this tree yet (the Jolt scene module)";
  }
  const Scene s = jolt_test_vehicle();
  std::optional<FieldError> error;
  auto world = kJoltSceneBackend.build(SceneBuild{&s, {kJoltTestSpring, kJoltTestSpring}, jolt_test_defaults()}, error);
  ASSERT_TRUE(world) << error->field << ": " << error->rule;
  std::vector<double> heave{world->body(1).centre.y()};
  for (int f = 0; f < frame_count(s.world); ++f) {
    world->step_frame(f);
    if (f < 120) heave.push_back(world->body(1).centre.y());
  }
  const ResponseFit fit = fit_response(heave, 1.0 / 60.0);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  std::printf("vehicle heave in jolt: f %.3f Hz zeta %.3f; chassis x at 6 s %.2f m\n", *fit.frequency_hz,
              *fit.damping_ratio, world->body(1).centre.x());
  EXPECT_NEAR(*fit.frequency_hz, 3.0, 0.3);
  EXPECT_GT(world->body(1).centre.x(), 8.0);
}

}  // namespace
}  // namespace softtune::scene
