// apply_scene_tuning: the page's tuning replaces each designer-tuned item's own, the step goes to the world,
// rigid joints stay rigid, and a bad tuning is refused at `tuning.<field>` before anything runs. The physics:
// a tuned vehicle's suspension measures the frequency the tuning asks for, not the preset's own.
#include "app/scene_tuning.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "app/simulate_app.h"
#include "codec/problem.h"

using nlohmann::json;
using softtune::app::apply_scene_tuning;

namespace {

json two_joint_scene() {
  return json::parse(R"({"name": "t", "world": {"fps": 60, "duration_s": 1},
    "joints": [{"id": "spring", "type": "distance", "response_frames": 30, "oscillation": "some", "mode": "exact"},
               {"id": "pin", "type": "revolute"}],
    "oscillators": [{"id": "a", "effective_mass": 2, "frequency_hz": 3, "damping_ratio": 0.1, "mode": "exact"},
                    {"id": "copy", "joint": "spring"}]})");
}

std::string refused_field(const json& tuning) {
  json scene = two_joint_scene();
  try {
    apply_scene_tuning(scene, tuning);
  } catch (const softtune::codec::Problem& p) {
    return p.field;
  }
  return "";
}

}  // namespace

TEST(SceneTuning, ReplacesTheDesignerFieldsOfTunedItemsOnly) {
  json scene = two_joint_scene();
  apply_scene_tuning(scene, {{"response_frames", 12}, {"damping_ratio", 0.3}, {"mode", "standard"}, {"fps", 120}, {"substeps", 4}});
  EXPECT_EQ(scene["world"], json({{"fps", 120}, {"duration_s", 1}, {"substeps", 4}}));
  const json& spring = scene["joints"][0];
  EXPECT_EQ(spring["response_frames"], 12);
  EXPECT_EQ(spring["damping_ratio"], 0.3);
  EXPECT_FALSE(spring.contains("oscillation"));
  EXPECT_EQ(spring["mode"], "standard");  // joints take the page's mode
  EXPECT_EQ(scene["joints"][1], json({{"id", "pin"}, {"type", "revolute"}}));  // rigid stays rigid
  const json& osc = scene["oscillators"][0];
  EXPECT_FALSE(osc.contains("frequency_hz"));
  EXPECT_EQ(osc["response_frames"], 12);
  EXPECT_EQ(osc["mode"], "exact");  // an oscillator keeps the mode it names
  EXPECT_EQ(scene["oscillators"][1], json({{"id", "copy"}, {"joint", "spring"}}));
}

TEST(SceneTuning, RefusesABadTuningAtItsField) {
  EXPECT_EQ(refused_field(json::array()), "tuning");
  EXPECT_EQ(refused_field({{"response_frames", 12}, {"oscillation", "some"}, {"stiffness", 3}}), "tuning.stiffness");
  EXPECT_EQ(refused_field({{"response_frames", 12}, {"oscillation", "lots"}}), "tuning.oscillation");
  EXPECT_EQ(refused_field({{"response_frames", -1}, {"oscillation", "some"}}), "tuning.response_frames");
  EXPECT_EQ(refused_field({{"response_frames", 12}, {"oscillation", "some"}, {"fps", "fast"}}), "tuning.fps");
  EXPECT_EQ(refused_field({{"response_frames", 12}, {"oscillation", "some"}, {"substeps", 0}}), "tuning.substeps");
  EXPECT_EQ(refused_field({{"oscillation", "some"}}), "tuning.response_frames");
  EXPECT_EQ(refused_field({{"response_frames", 12}}), "tuning.oscillation");
  EXPECT_EQ(refused_field({{"response_frames", 12}, {"oscillation", "some"}, {"damping_ratio", 0.5}}), "tuning.oscillation");
}

// The tuning reaches Box2D: the preset asks 20 frames at 60 fps (3 Hz); tuned to 40 frames, each wheel joint
// gets k = m_eff (2 pi 1.5 Hz)^2 and c = 2 zeta m_eff omega on its own effective mass (standard mode), and the
// rear suspension's travel swings measurably slower.
TEST(SceneTuning, AVehicleTunedSlowerGetsTheSoftSpringItAskedFor) {
  const std::string dir = SOFTTUNE_PRESETS_DIR;
  const json preset = softtune::app::run_simulate({{"preset", "vehicle_per_spring"}}, dir);
  const json tuned = softtune::app::run_simulate(
      {{"preset", "vehicle_per_spring"}, {"tuning", {{"response_frames", 40}, {"oscillation", "some"}, {"mode", "standard"}}}}, dir);
  const double omega = 2 * M_PI * 1.5;
  for (const json& j : tuned["joints"]) {
    const double m = j["effective_mass"].get<double>();
    EXPECT_NEAR(j["stiffness"].get<double>(), m * omega * omega, 1e-9 * m * omega * omega) << j["id"];
    EXPECT_NEAR(j["damping"].get<double>(), 2 * 0.5 * m * omega, 1e-9 * m * omega) << j["id"];
  }
  const auto measured = [](const json& out, const char* probe) {
    for (const json& p : out["probes"]) {
      if (p["id"] == probe) return p["measured"]["frequency_hz"].get<double>();
    }
    return 0.0;
  };
  EXPECT_LT(measured(tuned, "rear_travel"), 0.75 * measured(preset, "rear_travel"));
}
