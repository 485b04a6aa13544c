#include "codec/scene_engine_codec.h"

#include <gtest/gtest.h>

#include <string>

#include "codec/problem.h"
#include "softtune/engines/scene_backends.h"
#include "softtune/scene/box2d_backend.h"

using nlohmann::json;
using namespace softtune::codec;

namespace {

SceneEngineChoice scene_engine_read(const json& doc) {
  ObjectReader r = read_object(doc, "");
  SceneEngineChoice c = read_scene_engine(r, softtune::engines::scene_backends());
  r.finish();  // engine and engine_settings are read, nothing else is there
  return c;
}

std::string scene_engine_refusal(const json& doc) {
  try {
    scene_engine_read(doc);
    return "accepted";
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return p.field + ": " + p.detail;
  }
}

const softtune::scene::SceneBackend& scene_engine_box2d() { return softtune::scene::kBox2DV24SceneBackend; }

}  // namespace

TEST(SceneEngineCodec, AbsentIsBox2DWithItsDefaults) {
  const SceneEngineChoice c = scene_engine_read(json::object());
  ASSERT_EQ(c.backend, &scene_engine_box2d());
  ASSERT_EQ(c.settings.size(), scene_engine_box2d().settings.size());
  for (std::size_t i = 0; i < c.settings.size(); ++i) EXPECT_EQ(c.settings[i], scene_engine_box2d().settings[i].default_value);
  EXPECT_EQ(scene_engine_read(json{{"engine", "box2d_v2_4"}}).backend, &scene_engine_box2d());
}

// Each backend's own settings: a legal value is taken, one past its range refused naming it; a name the engine
// does not have is refused (Box2D 2.4 has none: its iterations are the scene's world fields).
TEST(SceneEngineCodec, SettingsAreTheBackendsOwnAndWithinTheirRanges) {
  for (const softtune::scene::SceneBackend* b : softtune::engines::scene_backends()) {
    for (std::size_t i = 0; i < b->settings.size(); ++i) {
      const softtune::engines::SettingSpec& spec = b->settings[i];
      if (!spec.choices.empty()) continue;  // the choice rule: tests/codec/settings_codec_test.cpp
      const std::string name(spec.name);
      const double legal = spec.max > spec.default_value ? spec.max : spec.min;
      const SceneEngineChoice c = scene_engine_read(json{{"engine", b->name}, {"engine_settings", {{name, legal}}}});
      EXPECT_EQ(c.settings[i], legal) << b->name << " " << name;
      EXPECT_EQ(scene_engine_refusal(json{{"engine", b->name}, {"engine_settings", {{name, spec.max + 1}}}})
                    .rfind("engine_settings." + name + ": must be", 0), 0u) << b->name << " " << name;
    }
  }
  EXPECT_EQ(scene_engine_refusal(json{{"engine_settings", {{"velocityIterations", 8}}}}).rfind("engine_settings.velocityIterations: ", 0), 0u);
  EXPECT_EQ(scene_engine_refusal(json{{"engine_settings", {{"noSuchSetting", 1}}}}).rfind("engine_settings.noSuchSetting: ", 0), 0u);
  EXPECT_EQ(scene_engine_refusal(json{{"engine_settings", 8}}).rfind("engine_settings: must be an object", 0), 0u);
  EXPECT_EQ(scene_engine_read(json{{"engine_settings", json::object()}}).settings.size(), scene_engine_box2d().settings.size());
}

TEST(SceneEngineCodec, AnUnknownEngineIsRefusedListingTheKnownOnes) {
  const std::string refusal = scene_engine_refusal(json{{"engine", "havok"}});
  EXPECT_EQ(refusal.rfind("engine: is not a scene engine of this build: one of ", 0), 0u) << refusal;
  for (const softtune::scene::SceneBackend* b : softtune::engines::scene_backends()) {
    EXPECT_NE(refusal.find("\"" + std::string(b->name) + "\""), std::string::npos) << refusal;
  }
  EXPECT_EQ(scene_engine_refusal(json{{"engine", 3}}).rfind("engine: must be a string", 0), 0u);
}

TEST(SceneEngineCodec, TheChoiceReachesTheRunOptionsAndTheAnswerNamesIt) {
  const SceneEngineChoice c = scene_engine_read(json::object());
  softtune::scene::RunOptions options;
  apply_scene_engine(c, options);
  EXPECT_EQ(options.backend, c.backend);
  EXPECT_EQ(options.engine_settings, c.settings);
  const json planned = scene_engine_json(c);
  EXPECT_EQ(planned["name"], "box2d_v2_4");
  EXPECT_EQ(planned["version"], std::string(scene_engine_box2d().version));
  EXPECT_EQ(planned["settings"].size(), scene_engine_box2d().settings.size());
  // Another setting is another cache key, another engine too; the same choice the same key.
  SceneEngineChoice other = c;
  other.settings.push_back(1.0);
  EXPECT_NE(scene_engine_key(c), scene_engine_key(other));
  SceneEngineChoice renamed = c;
  const softtune::scene::SceneBackend other_engine{"other_engine", "v", {}, nullptr, nullptr, nullptr};
  renamed.backend = &other_engine;
  EXPECT_NE(scene_engine_key(c), scene_engine_key(renamed));
  EXPECT_EQ(scene_engine_key(c), scene_engine_key(scene_engine_read(json::object())));
}
