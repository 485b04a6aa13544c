// The scene codec (scene_codec.cpp) through the simulate request: a full scene, bare or under "scene", is decoded
// and run; a bad one is refused naming the field (validation) or the JSON pointer and rule (the schema).
#include "codec/scene_codec.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "app/simulate_app.h"
#include "codec/problem.h"
#include "../presets_dir.h"

namespace softtune::codec {
namespace {

using namespace softtune::app;

using nlohmann::json;

using test_support::kPresets;

TEST(Simulate, AFullSceneIsValidatedAndRun) {
  json scene = load_preset(kPresets, "mouse");
  EXPECT_EQ(run_simulate(scene, kPresets)["name"], "mouse");
  EXPECT_EQ(run_simulate({{"scene", scene}}, kPresets)["name"], "mouse");
  scene["joints"][0]["body_b"] = "nobody";
  try {
    run_simulate(scene, kPresets);
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "joints.0.body_b");
  }
  scene = load_preset(kPresets, "mouse");
  scene["joints"][0]["response_frames"] = -3;
  try {
    run_simulate(scene, kPresets);
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.field, "joints.0.response_frames");  // the dotted path, not the schema's pointer
    EXPECT_NE(p.detail.find("must be >= 0.01"), std::string::npos);
  }
}

}  // namespace
}  // namespace softtune::codec
