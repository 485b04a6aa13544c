#include "codec/settings_codec.h"

#include <gtest/gtest.h>

#include <string>

#include "codec/problem.h"
#include "softtune/engines/engine_model.h"

using nlohmann::json;
using softtune::codec::Problem;
using softtune::codec::read_setting_values;

namespace {

// The specs of a modelled engine (core/src/engines/<engine>.cpp): the real settings a request names.
std::span<const softtune::engines::SettingSpec> settings_codec_specs(std::string_view engine) {
  for (const softtune::engines::EngineModel* m : softtune::engines::engine_models()) {
    if (m->name == engine) return m->settings;
  }
  ADD_FAILURE() << "no engine model " << engine;
  return {};
}

std::string settings_codec_refusal(const json& doc, std::string_view engine) {
  try {
    read_setting_values(doc, "engine_settings", settings_codec_specs(engine));
    return "accepted";
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return p.field + ": " + p.detail;
  }
}

}  // namespace

TEST(SettingsCodec, GivenSettingsReplaceDefaultsAndTheRestKeepThem) {
  // Box2D v3: subStepCount (integer, default 4), enableWarmStarting (a switch, default true).
  const auto v3 = settings_codec_specs("box2d_v3");
  ASSERT_EQ(v3.size(), 2u);
  EXPECT_EQ(read_setting_values(json::object(), "engine_settings", v3), (softtune::engines::SettingValues{4, 1}));
  EXPECT_EQ(read_setting_values(json{{"subStepCount", 8}}, "engine_settings", v3), (softtune::engines::SettingValues{8, 1}));
  EXPECT_EQ(read_setting_values(json{{"enableWarmStarting", false}}, "engine_settings", v3),
            (softtune::engines::SettingValues{4, 0}));
  // A choice is read by its name, and stored as its index (MuJoCo's integrator: Euler is the first).
  const auto mujoco = settings_codec_specs("mujoco");
  const auto values = read_setting_values(json{{"integrator", "implicit"}}, "engine_settings", mujoco);
  ASSERT_FALSE(values.empty());
  EXPECT_EQ(mujoco[0].choices[static_cast<std::size_t>(values[0])], "implicit");
}

TEST(SettingsCodec, RefusalsNameTheSettingAndTheRule) {
  EXPECT_EQ(settings_codec_refusal(json{{"subStepCount", 0}}, "box2d_v3"),
            "engine_settings.subStepCount: must be an integer in [1, 1000]");
  EXPECT_EQ(settings_codec_refusal(json{{"subStepCount", 2.5}}, "box2d_v3").rfind("engine_settings.subStepCount: ", 0), 0u);
  EXPECT_EQ(settings_codec_refusal(json{{"enableWarmStarting", 1}}, "box2d_v3"),
            "engine_settings.enableWarmStarting: must be true or false");
  EXPECT_EQ(settings_codec_refusal(json{{"substeps", 4}}, "box2d_v3").rfind("engine_settings.substeps: ", 0), 0u);
  EXPECT_EQ(settings_codec_refusal(json{{"integrator", "RK2"}}, "mujoco").rfind("engine_settings.integrator: ", 0), 0u);
  EXPECT_EQ(settings_codec_refusal(json::array(), "box2d_v3").rfind("engine_settings: ", 0), 0u);
}
