// A scene's modal tuning (scene/modal_tuning.h) confirmed by the Box2D simulation: the vehicle's chassis heave
// solved in exact mode at 30, 60, 120 and 144 fps is measured (suspension travel, response fit) within 3 % and
// 0.05 of the request (at 120 and 144 fps within 0.1 % and 0.005: the tyres start where Box2D's contact leaves
// them, so nothing but the heave moves the travel; docs/scenes.md); the per-spring vehicle misses it by more
// than half.
#include "softtune/scene/modal_tuning.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/scene/runner.h"
#include "../presets_dir.h"
#include "probe_result.h"

namespace softtune::scene {
namespace {

using test_support::kPresets;

using test::probe_result;

TEST(ModalTuning, ExactHeaveIsWhatBox2DMeasuresAt30To144Fps) {
  for (double fps : {30.0, 60.0, 120.0, 144.0}) {
    nlohmann::json doc = app::load_preset(kPresets, "vehicle");
    doc["world"]["fps"] = fps;
    const Scene scene = codec::decode_scene(doc);
    const SceneResult run = run_scene(scene);
    ASSERT_FALSE(run.error) << run.error->field << ": " << run.error->rule;
    ASSERT_TRUE(run.modal_tuning);
    const ModalTargetResult& target = run.modal_tuning->targets.at(0);
    EXPECT_EQ(target.mode, "chassis heave");
    ASSERT_TRUE(target.predicted);
    EXPECT_NEAR(target.predicted->frequency_hz, 3.0, 1e-6) << fps;  // the linear model, exact for the step
    EXPECT_NEAR(target.predicted->damping_ratio, 0.5, 1e-6) << fps;
    // The chassis centre: the heave's coordinate, which the pitch the preset kicks does not move.
    const ProbeResult& travel = probe_result(run, "heave");
    ASSERT_TRUE(travel.frequency_error && travel.damping_ratio_error);
    EXPECT_LT(std::abs(*travel.frequency_error), 0.03) << fps;
    EXPECT_LT(std::abs(*travel.damping_ratio_error), 0.05) << fps;
    if (fps >= 120.0) {  // Box2D's 8 velocity iterations converge at these steps (docs/scenes.md): the model's own poles
      EXPECT_LT(std::abs(*travel.frequency_error), 2e-3) << fps;
      EXPECT_LT(std::abs(*travel.damping_ratio_error), 5e-3) << fps;
    }
    EXPECT_EQ(*travel.requested_frequency_hz, 3.0);  // the probe is compared with the mode asked, not a spring
    // A joint's travel mixes the heave with the pitch: compared with nothing, not with the solve's spring.
    EXPECT_FALSE(probe_result(run, "rear_travel").requested_frequency_hz) << fps;
  }
}

// The pitch target is measured on its mode: the chassis is kicked into pitch at the start and its angle fitted
// before the motor starts (0-2 s), not in the drive into the stack.
TEST(ModalTuning, PitchTargetIsMeasuredOnThePitch) {
  for (double fps : {30.0, 60.0, 120.0, 144.0}) {
    nlohmann::json doc = app::load_preset(kPresets, "vehicle");
    doc["world"]["fps"] = fps;
    doc["modal_tuning"]["targets"] = {{{"body", "chassis"}, {"mode", "pitch"}, {"response_frames", 20}, {"oscillation", "some"}}};
    const SceneResult run = run_scene(codec::decode_scene(doc));
    ASSERT_FALSE(run.error) << run.error->field << ": " << run.error->rule;
    EXPECT_EQ(run.modal_tuning->targets.at(0).probe, "pitch");
    const ProbeResult& pitch = probe_result(run, "pitch");
    ASSERT_TRUE(pitch.frequency_error && pitch.damping_ratio_error) << fps;
    EXPECT_LT(std::abs(*pitch.frequency_error), 0.01) << fps;
    EXPECT_LT(std::abs(*pitch.damping_ratio_error), 0.01) << fps;
  }
}

TEST(ModalTuning, PerSpringVehicleMissesTheHeave) {
  const SceneResult run = run_scene(codec::decode_scene(app::load_preset(kPresets, "vehicle_per_spring")));
  const ProbeResult& heave = probe_result(run, "heave");
  ASSERT_TRUE(heave.measured.frequency_hz);
  EXPECT_LT(*heave.measured.frequency_hz / 3.0 - 1.0, -0.5);
  EXPECT_FALSE(run.modal_tuning);
}

}  // namespace
}  // namespace softtune::scene
