// The simulate use case (simulate_app.cpp) on the real preset files: the oscillator runs without Box2D, probes
// carry requested, measured, error and series, and snapshots come only when asked.
#include "app/simulate_app.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include "../presets_dir.h"

namespace softtune::codec {
namespace {

using namespace softtune::app;

using nlohmann::json;

using test_support::kPresets;

TEST(Simulate, OscillatorPresetHasNoBox2DStage) {
  const json out = run_simulate({{"preset", "oscillator"}}, kPresets);
  for (const json& stage : out["stages"]) EXPECT_EQ(stage.get<std::string>().find("box2d"), std::string::npos) << stage;
  EXPECT_NE(std::find(out["stages"].begin(), out["stages"].end(), "core_integrator"), out["stages"].end());
  EXPECT_FALSE(out.contains("snapshots"));
}

TEST(Simulate, ProbesCarryRequestedMeasuredErrorAndSeries) {
  const json out = run_simulate({{"preset", "buddhas"}}, kPresets);
  ASSERT_EQ(out["probes"].size(), 4u);
  for (const json& p : out["probes"]) {
    for (const char* key : {"frequency_hz", "damping_ratio"}) EXPECT_TRUE(p["requested"][key].is_number());
    for (const char* key : {"frequency_hz", "damping_ratio", "overshoot", "settle_frames"}) EXPECT_TRUE(p["measured"].contains(key));
    EXPECT_LT(std::abs(p["error"]["frequency"].get<double>()), 0.03);
    EXPECT_TRUE(p["error"]["damping_ratio"].is_number());
    EXPECT_EQ(p["series"]["time"].size(), p["series"]["value"].size());
    EXPECT_EQ(p["series"]["time"].size(), static_cast<std::size_t>(out["frames"].get<int>() + 1));
  }
  const json reduced = run_simulate({{"preset", "buddhas"}, {"mass_model", "box2d_reduced"}}, kPresets);
  EXPECT_EQ(reduced["mass_model"], "box2d_reduced");
  EXPECT_GT(reduced["probes"][3]["error"]["frequency"].get<double>(), 0.3);
}

TEST(Simulate, FramesOnlyWhenAsked) {
  const json out = run_simulate({{"preset", "mouse"}, {"frames", true}, {"frame_stride", 30}}, kPresets);
  ASSERT_TRUE(out.contains("snapshots"));
  EXPECT_EQ(out["snapshots"].size(), 7u);  // frames 0, 30, ..., 180
  EXPECT_EQ(out["snapshots"][0]["bodies"][0]["polygon"].size(), 4u);
  EXPECT_NE(std::find(out["stages"].begin(), out["stages"].end(), "snapshots"), out["stages"].end());
}

}  // namespace
}  // namespace softtune::codec
