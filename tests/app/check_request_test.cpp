// The check contract as a request (POST /api/v1/check; the CLI builds the same from its flags): every field
// bounded and named when refused, presets by name or inline scenes, JSON or JUnit.
#include "app/check_request.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "codec/problem.h"

namespace softtune::app {
namespace {

using nlohmann::json;

std::string refused_field(const json& request) {
  try {
    run_check_request(request, SOFTTUNE_PRESETS_DIR);
  } catch (const codec::Problem& p) {
    return std::to_string(p.status) + " " + p.field;
  }
  return "(accepted)";
}

TEST(CheckRequest, ShardsAreIOfN) {
  EXPECT_EQ(parse_shard("2/5", "--shard").index, 2);
  EXPECT_EQ(parse_shard("2/5", "--shard").count, 5);
  for (const char* bad : {"0/3", "4/3", "3", "1/0", "a/b", "1/3/4", "-1/3", "1/100000"}) {
    EXPECT_THROW(parse_shard(bad, "--shard"), codec::Problem) << bad;
  }
}

TEST(CheckRequest, BadFieldsAreNamed) {
  EXPECT_EQ(refused_field({{"presets", {"mouse", "nope"}}}), "404 presets.1");
  EXPECT_EQ(refused_field({{"presets", {"mouse", "mouse"}}}), "422 presets.1");
  EXPECT_EQ(refused_field({{"presets", json::array()}}), "422 presets");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"fps", {60, 0}}}), "422 fps.1");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"substeps", {1.5}}}), "422 substeps.0");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"shard", "3/2"}}), "422 shard");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"format", "xml"}}), "422 format");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"baseline", {{"cases", 1}}}}), "422 baseline.softtune_baseline");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"jobs", 4}}), "422 jobs");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"engine", "havok"}}), "422 engine");
  EXPECT_EQ(refused_field({{"presets", {"mouse"}}, {"engine_settings", {{"noSuchSetting", 1}}}}), "422 engine_settings.noSuchSetting");
  EXPECT_EQ(refused_field({{"scenes", {{{"name", "x"}, {"world", {{"fps", 0}, {"duration_s", 1}}}}}}}), "422 scenes.0.world.fps");
  // every preset at 16 rates x 16 substep counts: refused before any step
  json many = json::array(), subs = json::array();
  for (int i = 0; i < 16; ++i) {
    many.push_back(30 + 10 * i);
    subs.push_back(i + 1);
  }
  EXPECT_EQ(refused_field({{"fps", many}, {"substeps", subs}}), "422 presets, scenes, fps, substeps");
}

// The engine every case runs in is named in the report; the default engine named checks as before.
TEST(CheckRequest, TheReportNamesTheEngineItRan) {
  const CheckAnswer named = run_check_request({{"presets", {"mouse"}}, {"engine", "box2d_v2_4"}}, SOFTTUNE_PRESETS_DIR);
  const CheckAnswer plain = run_check_request({{"presets", {"mouse"}}}, SOFTTUNE_PRESETS_DIR);
  EXPECT_EQ(named.json["engine"]["name"], "box2d_v2_4");
  EXPECT_TRUE(named.json["passed"].get<bool>());
  ASSERT_EQ(named.json["cases"].size(), plain.json["cases"].size());
  EXPECT_EQ(named.json["cases"][0]["figures"], plain.json["cases"][0]["figures"]);
  // In an engine that cannot represent the preset, its case fails with the engine's refusal.
  const CheckAnswer bullet = run_check_request({{"presets", {"mouse"}}, {"engine", "bullet"}}, SOFTTUNE_PRESETS_DIR);
  EXPECT_EQ(bullet.json["engine"]["name"], "bullet");
  EXPECT_FALSE(bullet.json["passed"].get<bool>());
  EXPECT_EQ(bullet.json["cases"][0]["problem"]["field"], "joints.0.max_force");
}

TEST(CheckRequest, InlineScenesAndPresetsAnswerJsonOrJunit) {
  json scene = load_preset(SOFTTUNE_PRESETS_DIR, "oscillator");
  scene["name"] = "my_oscillator";
  const CheckAnswer a = run_check_request({{"presets", {"mouse"}}, {"scenes", {scene}}, {"fps", {30, 60}}}, SOFTTUNE_PRESETS_DIR);
  ASSERT_FALSE(a.junit);
  EXPECT_TRUE(a.json["passed"].get<bool>());
  ASSERT_EQ(a.json["cases"].size(), 4u);
  EXPECT_EQ(a.json["cases"][0]["key"], "mouse@30x1");
  EXPECT_EQ(a.json["cases"][3]["key"], "my_oscillator@60x1");

  const CheckAnswer j = run_check_request({{"presets", {"mouse"}}, {"format", "junit"}}, SOFTTUNE_PRESETS_DIR);
  ASSERT_TRUE(j.junit);
  EXPECT_NE(j.xml.find("<testcase classname=\"softtune.check.mouse\" name=\"30 fps x 1\""), std::string::npos) << j.xml;
}

}  // namespace
}  // namespace softtune::app
