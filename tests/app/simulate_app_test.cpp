// The simulate use case (simulate_app.cpp) on the real preset files: the oscillator runs without Box2D, probes
// carry requested, measured, error and series, and snapshots come only when asked.
#include "app/simulate_app.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../presets_dir.h"
#include "app/preset_store.h"
#include "codec/problem.h"
#include "softtune/engines/scene_backends.h"

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

// Each tuned joint's Box2D 2.4 values, typed back into `doc` as `typed` with the tuning (and any modal tuning)
// removed: the scene a designer has in the game once they typed what simulate said. Oscillators copying a joint
// copy a tuning, which a typed joint no longer has: they and their probes go.
json typed_back(json doc, const json& answer) {
  static const char* kDesigner[] = {"response_frames", "basis_fps", "frequency_hz", "oscillation", "damping_ratio", "mode"};
  for (std::size_t i = 0; i < answer["joints"].size(); ++i) {
    const json& j = answer["joints"][i];
    if (!j["tuned"].get<bool>()) continue;
    for (const char* k : kDesigner) doc["joints"][i].erase(k);
    doc["joints"][i]["typed"] = j["engines"]["box2d_v2_4"]["parameters"];
  }
  doc.erase("modal_tuning");
  doc.erase("expectations");
  if (doc.contains("oscillators")) {
    json kept = json::array(), probes = json::array();
    std::vector<std::string> dropped;
    for (const json& o : doc["oscillators"]) {
      if (o.contains("joint")) dropped.push_back(o["id"]);
      else kept.push_back(o);
    }
    doc["oscillators"] = kept;
    for (const json& p : doc["probes"]) {
      if (std::find(dropped.begin(), dropped.end(), p.value("oscillator", "")) == dropped.end()) probes.push_back(p);
    }
    doc["probes"] = probes;
  }
  return doc;
}

const json* probe_named(const json& answer, const std::string& id) {
  for (const json& p : answer["probes"]) {
    if (p["id"] == id) return &p;
  }
  return nullptr;
}

// The copy test (issue 30): for every preset with a tuned joint, the values simulate tells the designer to
// type into Box2D 2.4 (each tuned joint's engines.box2d_v2_4.parameters), typed back as `typed` into the same
// scene with the tuning removed, measure the same: each mode target and each probe within 1 % / 0.01.
TEST(Simulate, WhatToTypeMeasuresWhatItSays) {
  int presets = 0;
  for (const std::string& name : app::list_presets(kPresets)) {
    const json answer = run_simulate({{"preset", name}}, kPresets);
    const bool tuned = std::any_of(answer["joints"].begin(), answer["joints"].end(), [](const json& j) { return j["tuned"].get<bool>(); });
    if (!tuned) continue;
    ++presets;
    const json again = run_simulate({{"scene", typed_back(app::load_preset(kPresets, name), answer)}}, kPresets);
    for (const json& j : again["joints"]) EXPECT_FALSE(j["tuned"].get<bool>()) << name << " " << j["id"];
    std::vector<std::pair<std::string, json>> measured;  // (what, {frequency_hz, damping_ratio})
    if (answer.contains("modal_tuning")) {
      for (const json& t : answer["modal_tuning"]["targets"]) {
        ASSERT_TRUE(t["measured"].is_object()) << name << " " << t["mode"];
        measured.emplace_back(t["probe"].get<std::string>(), t["measured"]);
      }
    }
    for (const json& p : answer["probes"]) {
      if (p["measured"]["frequency_hz"].is_number() && p["measured"]["damping_ratio"].is_number() && probe_named(again, p["id"]))
        measured.emplace_back(p["id"].get<std::string>(), p["measured"]);
    }
    EXPECT_FALSE(measured.empty()) << name;
    for (const auto& [probe, m] : measured) {
      const json* typed = probe_named(again, probe);
      ASSERT_NE(typed, nullptr) << name << " " << probe;
      const json& t = (*typed)["measured"];
      ASSERT_TRUE(t["frequency_hz"].is_number()) << name << " " << probe;
      EXPECT_NEAR(t["frequency_hz"].get<double>() / m["frequency_hz"].get<double>(), 1.0, 0.01) << name << " " << probe;
      EXPECT_NEAR(t["damping_ratio"].get<double>(), m["damping_ratio"].get<double>(), 0.01) << name << " " << probe;
    }
  }
  EXPECT_GE(presets, 7);  // bridge, bridge_deck, buddhas, heavy_on_light, mouse, stiff, vehicle, vehicle_per_spring
}

// One answer per solved joint: the vehicle's suspension says what to type in its own def (b2WheelJointDef),
// the solved k, c the summary bar and modal_tuning.groups show, and what it asked -- the chassis heave.
TEST(Simulate, SolvedJointsCarryTheSolveAndTheTarget) {
  const json answer = run_simulate({{"preset", "vehicle"}}, kPresets);
  const json& group = answer["modal_tuning"]["groups"][0];
  const json& target = answer["modal_tuning"]["targets"][0];
  for (const json& j : answer["joints"]) {
    ASSERT_TRUE(j["tuned"].get<bool>());
    const json& box2d = j["engines"]["box2d_v2_4"];
    EXPECT_EQ(box2d["parameters"]["b2WheelJointDef::stiffness"], group["stiffness"]) << j["id"];
    EXPECT_EQ(box2d["parameters"]["b2WheelJointDef::damping"], group["damping"]) << j["id"];
    EXPECT_EQ(box2d["exact"], box2d["parameters"]);
    EXPECT_EQ(box2d["basis"], "scene_run");
    EXPECT_EQ(box2d["predicted"]["frequency_hz"], target["measured"]["frequency_hz"]);
    EXPECT_EQ(j["requested"]["frequency_hz"], target["requested"]["frequency_hz"]);
    EXPECT_EQ(j["requested"]["damping_ratio"], target["requested"]["damping_ratio"]);
    EXPECT_EQ(j["requested"]["mode"], "chassis heave");
    EXPECT_EQ(j["solved_by"]["group"], "suspension");
    for (const char* other : {"box2d_v3", "jolt", "mujoco", "physx", "rapier"}) {
      if (j["engines"].contains(other) && j["engines"][other].contains("parameters")) {
        EXPECT_EQ(j["engines"][other]["basis"], "per_joint_model") << other;
      }
    }
    // Warnings speak of what was asked: nothing about the solve's per-spring equivalent request.
    for (const json& w : j["warnings"]) EXPECT_EQ(w["message"].get<std::string>().find("asked frequency"), std::string::npos) << w;
    EXPECT_EQ(j["answer"]["k"], group["stiffness"]);
    EXPECT_EQ(j["answer"]["requested"]["frequency_hz"], target["requested"]["frequency_hz"]);
  }
  for (const json& j : answer["modal_tuning"]["joints"]) EXPECT_EQ(j["engines"]["box2d_v2_4"]["parameters"]["b2WheelJointDef::stiffness"], group["stiffness"]);
}

// The heave probe (the chassis centre, on the rear suspension) is compared with the target it measures, not with
// the solve's per-joint request; the pitch probe, which no target names, with nothing.
TEST(Simulate, HeaveProbeRequestIsTheTargets) {
  const json answer = run_simulate({{"preset", "vehicle"}}, kPresets);
  const json& asked = answer["modal_tuning"]["targets"][0]["requested"];
  const json* heave = probe_named(answer, "heave");
  ASSERT_NE(heave, nullptr);
  EXPECT_EQ((*heave)["requested"]["frequency_hz"], asked["frequency_hz"]);
  EXPECT_EQ((*heave)["requested"]["damping_ratio"], asked["damping_ratio"]);
  EXPECT_LT(std::abs((*heave)["error"]["frequency"].get<double>()), 0.03);
  EXPECT_TRUE((*probe_named(answer, "pitch"))["requested"]["frequency_hz"].is_null());
}

// `typed` takes exactly the names of the joint's def; anything else is a 422 naming the field.
TEST(Simulate, TypedRefusesNamesAndValuesNotTheEngines) {
  json doc = app::load_preset(kPresets, "vehicle_per_spring");
  for (const char* k : {"response_frames", "oscillation"}) doc["joints"][0].erase(k);
  auto refused = [&](const json& typed) -> std::string {
    json d = doc;
    d["joints"][0]["typed"] = typed;
    try {
      run_simulate({{"scene", d}}, kPresets);
    } catch (const Problem& p) {
      EXPECT_EQ(p.status, 422);
      return p.field;
    }
    return "(accepted)";
  };
  EXPECT_EQ(refused({{"b2DistanceJointDef::stiffness", 100.0}, {"b2DistanceJointDef::damping", 1.0}}),
            "scene.joints.0.typed.b2DistanceJointDef::damping");  // the first name, in key order
  EXPECT_EQ(refused({{"b2WheelJointDef::stiffness", 100.0}}), "scene.joints.0.typed.b2WheelJointDef::damping");
  EXPECT_EQ(refused({{"b2WheelJointDef::stiffness", -1.0}, {"b2WheelJointDef::damping", 1.0}}),
            "scene.joints.0.typed.b2WheelJointDef::stiffness");
  EXPECT_EQ(refused({{"b2WheelJointDef::stiffness", 100.0}, {"b2WheelJointDef::damping", "soft"}}).rfind("scene.joints.0.typed", 0), 0u);
  EXPECT_EQ(refused({{"b2WheelJointDef::stiffness", 100.0}, {"b2WheelJointDef::damping", -10.0}}),
            "scene.joints.0.typed.b2WheelJointDef::damping");  // damping + h k < 0: no positive gamma
  json both = doc;
  both["joints"][0]["typed"] = {{"b2WheelJointDef::stiffness", 100.0}, {"b2WheelJointDef::damping", 1.0}};
  both["joints"][0]["frequency_hz"] = 2.0;
  both["joints"][0]["damping_ratio"] = 0.5;
  EXPECT_THROW(run_simulate({{"scene", both}}, kPresets), Problem);
  // Accepted, it runs as typed: not tuned, no request, measured.
  json ok = doc;
  ok["joints"][0]["typed"] = {{"b2WheelJointDef::stiffness", 4700.61}, {"b2WheelJointDef::damping", 173.089}};
  const json run = run_simulate({{"scene", ok}}, kPresets);
  EXPECT_TRUE(run["joints"][0]["typed"].get<bool>());
  EXPECT_FALSE(run["joints"][0]["tuned"].get<bool>());
  EXPECT_TRUE((*probe_named(run, "rear_travel"))["requested"]["frequency_hz"].is_null());
  EXPECT_TRUE((*probe_named(run, "rear_travel"))["measured"]["frequency_hz"].is_number());
}

// `engine` (issue 32): naming the default engine answers exactly as before, and every answer says which engine
// ran, its version and the settings it ran with; each joint with a spring says what to type into it, under the
// engine's own names, the same values the 1-D Box2D export gives for the joint's k and c.
TEST(Simulate, TheDefaultEngineNamedAnswersAsBeforeAndSaysWhichRan) {
  const json before = run_simulate({{"preset", "buddhas"}}, kPresets);
  const json named = run_simulate({{"preset", "buddhas"}, {"engine", "box2d_v2_4"}}, kPresets);
  EXPECT_EQ(named, before);
  const scene::SceneBackend& box2d = *engines::find_scene_backend("box2d_v2_4");
  EXPECT_EQ(named["engine"]["name"], "box2d_v2_4");
  EXPECT_EQ(named["engine"]["version"], std::string(box2d.version));
  ASSERT_EQ(named["engine"]["settings"].size(), box2d.settings.size());
  for (const engines::SettingSpec& spec : box2d.settings) EXPECT_TRUE(named["engine"]["settings"].contains(spec.name)) << spec.name;
  int springs = 0;
  for (const json& j : named["joints"]) {
    if (!j["tuned"].get<bool>()) continue;
    ASSERT_TRUE(j.contains("parameters")) << j["id"];
    EXPECT_EQ(j["parameters"]["engine"], "box2d_v2_4");
    // Box2D 2.4 takes k and c as they are: the backend's fields are the joint def's stiffness and damping.
    const json& exported = j["engines"]["box2d_v2_4"]["parameters"];
    for (auto it = exported.begin(); it != exported.end(); ++it) {
      if (it.key().find("::stiffness") == std::string::npos && it.key().find("::damping") == std::string::npos) continue;
      ASSERT_TRUE(j["parameters"]["values"].contains(it.key())) << j["id"] << " " << it.key();
      EXPECT_NEAR(j["parameters"]["values"][it.key()].get<double>(), it.value().get<double>(), 1e-9 * std::abs(it.value().get<double>()))
          << j["id"] << " " << it.key();
    }
    ++springs;
  }
  EXPECT_GE(springs, 1);
}

TEST(Simulate, EngineSettingsRunAndUnknownEnginesOrSettingsAreRefused) {
  const json out = run_simulate({{"preset", "buddhas"}, {"engine_settings", json::object()}}, kPresets);
  EXPECT_EQ(out["engine"]["settings"].size(), engines::find_scene_backend("box2d_v2_4")->settings.size());
  const auto refused = [](const json& request) {
    try {
      run_simulate(request, kPresets);
    } catch (const Problem& p) {
      EXPECT_EQ(p.status, 422);
      return p.field + ": " + p.detail;
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refused({{"preset", "buddhas"}, {"engine", "havok"}}).rfind("engine: is not a scene engine of this build: one of \"box2d_v2_4\"", 0), 0u);
  EXPECT_EQ(refused({{"preset", "buddhas"}, {"engine_settings", {{"noSuchSetting", 1}}}}).rfind("engine_settings.noSuchSetting: ", 0), 0u);
  // Box2D 2.4's iterations are the scene's world fields, not engine settings.
  EXPECT_EQ(refused({{"preset", "buddhas"}, {"engine_settings", {{"velocityIterations", 8}}}}).rfind("engine_settings.velocityIterations: ", 0), 0u);
  // A bare scene carries the engine beside its own keys.
  json bare = app::load_preset(kPresets, "buddhas");
  bare.erase("expectations");
  bare["engine"] = "box2d_v2_4";
  EXPECT_EQ(run_simulate(bare, kPresets)["engine"]["name"], "box2d_v2_4");
}

// A scene the engine cannot represent is the backend's refusal: 422 naming the scene feature and the engine,
// never a run in another engine; one it can runs there and says so.
TEST(Simulate, AnEnginesRefusalNamesTheFeatureAndTheEngine) {
  try {
    run_simulate({{"preset", "mouse"}, {"engine", "bullet"}}, kPresets);
    ADD_FAILURE() << "bullet ran the capped mouse";
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "joints.0.max_force");
    EXPECT_NE(p.detail.find("bullet"), std::string::npos) << p.detail;
  }
  const json ode = run_simulate({{"preset", "buddhas"}, {"engine", "ode"}}, kPresets);
  EXPECT_EQ(ode["engine"]["name"], "ode");
  EXPECT_NE(std::find(ode["stages"].begin(), ode["stages"].end(), "engine_step"), ode["stages"].end());
  EXPECT_EQ(std::find(ode["stages"].begin(), ode["stages"].end(), "box2d_step"), ode["stages"].end());
  for (const json& j : ode["joints"]) {
    if (j.contains("parameters")) {
      EXPECT_EQ(j["parameters"]["engine"], "ode") << j["id"];
    }
  }
}

TEST(Simulate, TheSceneEnginesIndexListsEveryBackendWithItsSettings) {
  const json index = scene_engines_index();
  const auto all = engines::scene_backends();
  ASSERT_EQ(index["engines"].size(), all.size());
  EXPECT_EQ(index["engines"][0]["name"], "box2d_v2_4");
  EXPECT_TRUE(index["engines"][0]["default"].get<bool>());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const json& e = index["engines"][i];
    EXPECT_EQ(e["name"], std::string(all[i]->name));
    EXPECT_EQ(e["version"], std::string(all[i]->version));
    EXPECT_EQ(e["default"].get<bool>(), i == 0);
    ASSERT_EQ(e["settings"].size(), all[i]->settings.size());
    for (std::size_t k = 0; k < all[i]->settings.size(); ++k) {
      EXPECT_EQ(e["settings"][k]["name"], std::string(all[i]->settings[k].name));
      EXPECT_EQ(e["settings"][k]["min"], all[i]->settings[k].min);
      EXPECT_EQ(e["settings"][k]["max"], all[i]->settings[k].max);
    }
  }
}

}  // namespace
}  // namespace softtune::codec
