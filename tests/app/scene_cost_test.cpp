#include "app/scene_cost.h"

#include <gtest/gtest.h>

#include "app/budgets.h"
#include "app/preset_store.h"
#include "codec/scene_codec.h"

// Every shipped preset runs inside the budget (they are what the page and `softtune check` run).
TEST(SceneCost, EveryPresetFits) {
  const std::string dir = SOFTTUNE_SOURCE_DIR "/presets";
  for (const std::string& name : softtune::app::list_presets(dir)) {
    const auto scene = softtune::codec::decode_scene(softtune::app::load_preset(dir, name));
    softtune::scene::RunOptions frames;
    frames.record_frames = true;
    const auto cost = softtune::app::scene_cost(scene, frames, "");
    EXPECT_LT(cost.cpu_seconds, softtune::app::budgets::kCpuSeconds) << name;
    EXPECT_LT(cost.peak_bytes, softtune::app::budgets::kPeakBytes) << name;
  }
}

// 500 boxes for 40 s at 1000 fps (2e7 body-steps, inside the scene limits) is 7-13 s of Box2D when they
// stay apart (0.35-0.65 us a body-step, bench/scene_price_bench.cpp), far more in contact.
TEST(SceneCost, ALongCrowdedSceneIsOverAndNamesItsFieldsUnderThePrefix) {
  softtune::scene::Scene s;
  s.world.fps = 1000;
  s.world.duration_s = 40;
  s.bodies.resize(500);
  const auto cost = softtune::app::scene_cost(s, {}, "scene.");
  EXPECT_GT(cost.cpu_seconds, 3 * softtune::app::budgets::kCpuSeconds);
  ASSERT_GE(cost.fields.size(), 3u);
  EXPECT_EQ(cost.fields.front(), "scene.bodies");
  for (const std::string& f : cost.fields) EXPECT_EQ(f.rfind("scene.", 0), 0u) << f;
}
