// The linear model of Box2D scenes (scene/linearise.h) against the Box2D simulation of the same scene: the
// modes it predicts at the scene's step are what the probes' response fit measures.
#include "softtune/scene/linearise.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/scene/runner.h"
#include "../presets_dir.h"
#include "probe_result.h"

namespace softtune::scene {
namespace {

using test_support::kPresets;

Scene preset(const std::string& name) { return codec::decode_scene(app::load_preset(kPresets, name)); }

const modes::Mode& named(const std::vector<modes::Mode>& all, const std::string& name) {
  for (const auto& m : all) {
    if (m.name == name) return m;
  }
  ADD_FAILURE() << "no mode " << name;
  return all.front();
}

using test::probe_result;

// The vehicle at rest, its motor off and the box stack gone, kicked into pitch: Box2D's pitch and heave are the
// linear model's discrete poles (implicit Euler at the scene's step), to 0.1 % for the pitch it rings freely in.
// The heave is measured from the drop at t = 0 (not yet small motion): 1 %.
TEST(Linearise, VehicleModesAreWhatBox2DMeasures) {
  nlohmann::json doc = app::load_preset(kPresets, "vehicle_per_spring");
  for (auto& j : doc["joints"]) {
    j.erase("motor_speed");
    j.erase("max_motor_torque");
    j.erase("motor_start_s");
  }
  nlohmann::json bodies = nlohmann::json::array();
  for (auto& b : doc["bodies"]) {
    if (b["id"] == "chassis") b["angular_velocity"] = 0.5;
    if (b["id"].get<std::string>().rfind("box_", 0) != 0) bodies.push_back(b);
  }
  doc["bodies"] = bodies;
  doc["probes"] = {{{"id", "pitch"}, {"kind", "angle"}, {"body", "chassis"}, {"from_s", 1.0}},
                   {{"id", "heave"}, {"kind", "displacement"}, {"body", "chassis"}, {"axis", {0, 1}}, {"to_s", 2.0}}};
  doc["expectations"] = nlohmann::json::array();
  doc["world"]["duration_s"] = 4;
  const Scene scene = codec::decode_scene(doc);

  LinearisedScene lin;
  ASSERT_FALSE(linearise_scene(scene, MassModel::effective, {}, lin));
  EXPECT_TRUE(lin.settled);
  EXPECT_LT(lin.balance_residual, 5.0);  // N, against a 1500 N car
  EXPECT_EQ(lin.model.bodies.size(), 3u);
  EXPECT_EQ(lin.contact_points, 2);
  const auto modes = modes::modes_of(lin.model, modes::reduce(lin.model), lin.h);
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_TRUE(modes[0].free);  // the car rolls
  const modes::Mode& heave = named(modes, "chassis heave");
  const modes::Mode& pitch = named(modes, "chassis pitch");
  // Continuous heave: the docs' closed form f sqrt(2 m_eff / M) on the wheel-free m_eff (the tyres hold the wheels).
  const double m_eff = lin.joints[0].effective_mass;
  EXPECT_NEAR(heave.continuous->frequency_hz, 3.0 * std::sqrt(2.0 * m_eff / 120.0), 1e-3);

  const SceneResult run = run_scene(scene);
  const ResponseFit& heave_fit = probe_result(run, "heave").measured;
  const ResponseFit& pitch_fit = probe_result(run, "pitch").measured;
  ASSERT_TRUE(heave.discrete && pitch.discrete && heave_fit.frequency_hz && pitch_fit.frequency_hz);
  EXPECT_NEAR(pitch.discrete->frequency_hz / *pitch_fit.frequency_hz, 1.0, 1e-3);
  EXPECT_NEAR(pitch.discrete->damping_ratio, *pitch_fit.damping_ratio, 0.005);
  EXPECT_NEAR(heave.discrete->frequency_hz / *heave_fit.frequency_hz, 1.0, 0.01);
  EXPECT_NEAR(heave.discrete->damping_ratio, *heave_fit.damping_ratio, 0.01);
}

// The whole preset: the stack of boxes rests on contacts that hold it (no modes of its own), the motor start at
// 2 s ends the settling.
TEST(Linearise, VehiclePresetStopsAtTheMotorAndHoldsTheStack) {
  LinearisedScene lin;
  ASSERT_FALSE(linearise_scene(preset("vehicle_per_spring"), MassModel::effective, {}, lin));
  EXPECT_NEAR(lin.at_s, 2.0, 1e-9);
  EXPECT_EQ(lin.model.bodies.size(), 15u);
  const auto modes = modes::modes_of(lin.model, modes::reduce(lin.model), lin.h);
  EXPECT_EQ(modes.size(), 3u);  // roll, heave, pitch: the twelve boxes are held by their contacts
}

}  // namespace
}  // namespace softtune::scene
