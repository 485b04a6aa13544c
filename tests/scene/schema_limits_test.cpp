// presets/schema.json repeats a few of the scene limits (scene/limits.h) so that a preset author gets an
// early, pointed message; the limit itself is the constant, and the schema's bound must be that constant.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "softtune/scene/limits.h"
#include "softtune/validation.h"

namespace {

using nlohmann::json;
namespace sl = softtune::scene::limits;

const json& schema() {
  static const json doc = [] {
    std::ifstream in(SOFTTUNE_PRESETS_DIR "/schema.json");
    return json::parse(in);
  }();
  return doc;
}

const json& def(const std::string& pointer) { return schema().at(json::json_pointer("/$defs" + pointer)); }

TEST(SchemaLimits, WorldBoundsAreTheSceneLimits) {
  EXPECT_EQ(def("/world/properties/fps")["maximum"].get<double>(), sl::kMaxSceneFps);
  EXPECT_EQ(def("/world/properties/substeps")["maximum"].get<int>(), sl::kMaxSceneSubsteps);
  EXPECT_EQ(def("/world/properties/velocity_iterations")["maximum"].get<int>(), sl::kMaxIterations);
  EXPECT_EQ(def("/world/properties/position_iterations")["maximum"].get<int>(), sl::kMaxIterations);
  EXPECT_EQ(def("/world/properties/duration_s")["maximum"].get<double>(), sl::kMaxDurationS);
  EXPECT_EQ(def("/world/properties/bounds/items")["maximum"].get<double>(), sl::kMaxWorldCoordinate);
  EXPECT_EQ(def("/vec2/items")["maximum"].get<double>(), sl::kMaxWorldCoordinate);
}

TEST(SchemaLimits, BodyAndShapeBoundsAreTheSceneLimits) {
  EXPECT_EQ(def("/positive_size")["minimum"].get<double>(), sl::kMinSize);
  EXPECT_EQ(def("/positive_size")["maximum"].get<double>(), sl::kMaxSize);
  EXPECT_EQ(def("/body/properties/mass")["minimum"].get<double>(), sl::kMinBodyMass);
  EXPECT_EQ(def("/body/properties/mass")["maximum"].get<double>(), sl::kMaxBodyMass);
  EXPECT_EQ(def("/body/properties/density")["minimum"].get<double>(), sl::kMinDensity);
  EXPECT_EQ(def("/body/properties/density")["maximum"].get<double>(), sl::kMaxDensity);
  EXPECT_EQ(def("/body/properties/angular_velocity")["maximum"].get<double>(), sl::kMaxAngularSpeed);
  EXPECT_EQ(def("/joint/properties/length")["minimum"].get<double>(), sl::kMinJointLength);
}

TEST(SchemaLimits, TuningBoundsAreTheTuneRequestLimits) {
  namespace vl = softtune::limits;
  for (const char* owner : {"/joint", "/oscillator"}) {
    const json& p = def(std::string(owner) + "/properties");
    EXPECT_EQ(p["response_frames"]["minimum"].get<double>(), vl::kMinFrames) << owner;
    EXPECT_EQ(p["response_frames"]["maximum"].get<double>(), vl::kMaxFrames) << owner;
    EXPECT_EQ(p["basis_fps"]["maximum"].get<double>(), vl::kMaxFps) << owner;
    EXPECT_EQ(p["frequency_hz"]["maximum"].get<double>(), vl::kMaxFrequencyHz) << owner;
    EXPECT_EQ(p["damping_ratio"]["maximum"].get<double>(), vl::kMaxDampingRatio) << owner;
  }
  EXPECT_EQ(def("/oscillator/properties/effective_mass")["minimum"].get<double>(), vl::kMinMass);
  EXPECT_EQ(def("/oscillator/properties/effective_mass")["maximum"].get<double>(), vl::kMaxMass);
}

// A preset's rates and an expectation's fps / substeps lists (softtune check, docs/preset-ci.md).
TEST(SchemaLimits, RateListsAreTheSceneLimits) {
  EXPECT_EQ(def("/fps_list")["maxItems"].get<std::size_t>(), sl::kMaxRates);
  EXPECT_EQ(def("/fps_list/items")["minimum"].get<double>(), softtune::limits::kMinFps);
  EXPECT_EQ(def("/fps_list/items")["maximum"].get<double>(), sl::kMaxSceneFps);
  EXPECT_EQ(def("/substeps_list")["maxItems"].get<std::size_t>(), sl::kMaxRates);
  EXPECT_EQ(def("/substeps_list/items")["maximum"].get<int>(), sl::kMaxSceneSubsteps);
  EXPECT_EQ(schema().at("/properties/rates/properties/fps/$ref"_json_pointer), "#/$defs/fps_list");
  EXPECT_EQ(def("/expectation/properties/substeps/$ref"), "#/$defs/substeps_list");
}

}  // namespace
