// The simulate / presets / check contracts on the real preset files.
#include "codec/scene_codec.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/preset_store.h"
#include "app/simulate_app.h"
#include "codec/problem.h"

namespace softtune::codec {
namespace {

using namespace softtune::app;

using nlohmann::json;
namespace fs = std::filesystem;

const std::string kPresets = SOFTTUNE_PRESETS_DIR;

TEST(Presets, AllSevenFromTheTalkExistAndPassTheirChecks) {
  const auto names = list_presets(kPresets);
  for (const char* name : {"oscillator", "buddhas", "vehicle", "bridge", "mouse", "chain", "stiff"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
  }
  for (const std::string& name : names) {
    const json result = check_preset(load_preset(kPresets, name));
    EXPECT_TRUE(result["passed"].get<bool>()) << result.dump(1);
  }
  EXPECT_EQ(presets_index(kPresets)["presets"].size(), names.size());
}

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
    EXPECT_EQ(p.field, "/joints/0/response_frames");
    EXPECT_NE(p.detail.find("must be >= 0.01"), std::string::npos);
  }
}

TEST(Presets, AnInvalidPresetIsRefusedWithFilePointerAndRule) {
  const fs::path dir = fs::temp_directory_path() / "softtune_presets_test";
  fs::create_directories(dir);
  fs::copy_file(fs::path(kPresets) / "schema.json", dir / "schema.json", fs::copy_options::overwrite_existing);
  json broken = load_preset(kPresets, "stiff");
  broken["world"]["fps"] = 0;
  std::ofstream(dir / "broken.json") << broken.dump();
  try {
    load_preset(dir.string(), "broken");
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "/world/fps");
    EXPECT_NE(p.detail.find("broken.json"), std::string::npos);
    EXPECT_NE(p.detail.find("/world/fps must be >= 1"), std::string::npos);
  }
  EXPECT_THROW(load_preset(dir.string(), "../schema"), Problem);
  const json index = presets_index(dir.string());
  ASSERT_EQ(index["presets"].size(), 1u);
  EXPECT_FALSE(index["presets"][0]["valid"].get<bool>());
  EXPECT_EQ(index["presets"][0]["problem"]["field"], "/world/fps");
  try {
    load_preset(dir.string(), "absent");
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 404);
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace softtune::codec
