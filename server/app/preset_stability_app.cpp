#include "app/preset_stability_app.h"

#include <cstdio>

#include "app/preset_stability_cost.h"
#include "app/preset_store.h"
#include "codec/preset_limits_codec.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "codec/scene_engine_codec.h"
#include "app/simulate_app.h"

namespace softtune::app {

using nlohmann::json;

json run_preset_stability(const std::string& name, const std::string& presets_dir, const json& engine_doc) {
  codec::ObjectReader engine_reader = codec::read_object(engine_doc, "");
  const codec::SceneEngineChoice engine = read_request_engine(engine_reader);
  if (engine.backend->name != codec::kDefaultSceneEngine) {
    throw codec::invalid_field("engine", "the preset search bisects Box2D 2.4's own twin runs: " + std::string(engine.backend->name) +
                                             " has no stability search yet (simulate runs the preset in it)");
  }
  const scene::Scene scene = codec::decode_scene(load_preset(presets_dir, name));
  if (scene.modal_tuning) {
    throw codec::invalid_field("preset", "is modal-tuned (modal_tuning): its joints carry a modal solve, not their own frequency");
  }
  const scene::PresetLimitSettings settings;
  require_within_budget(preset_stability_cost(scene, settings));
  StageList stages;
  stages.add(Stage::validate);
  stages.add(Stage::scene_setup);
  stages.add(Stage::box2d_world);
  stages.add(Stage::box2d_step);
  const scene::PresetStabilityResult result = scene::preset_stability_limits(scene, settings);
  if (result.error) throw codec::invalid_field("preset." + result.error->field, result.error->rule);
  stages.add(Stage::stability_sweep);
  json out = codec::encode_preset_limits(name, settings, result, stages);
  out["engine"] = codec::scene_engine_json(engine);
  return out;
}

namespace {

std::string hz(const json& v) {
  if (v.is_null()) return "-";
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v.get<double>());
  return b;
}

}  // namespace

std::string preset_limits_table(const json& encoded) {
  const json& p = encoded.at("preset_limits");
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line, "%s: highest stable frequency per tuned joint in Box2D 2.4 (searched %s..%s Hz, bisected to %g)\n",
                p.at("preset").get<std::string>().c_str(), hz(p.at("searched_hz").at(0)).c_str(), hz(p.at("searched_hz").at(1)).c_str(),
                p.at("limit_relative_tolerance").get<double>());
  out += line;
  std::snprintf(line, sizeof line, "%-16s %10s %18s %16s %-20s %5s %8s\n", "joint", "asked Hz", "highest stable Hz", "unstable side Hz",
                "kind", "evals", "margin");
  out += line;
  for (const json& r : p.at("limits")) {
    std::snprintf(line, sizeof line, "%-16s %10s %18s %16s %-20s %5d %8s\n", r.at("joint").get<std::string>().c_str(),
                  hz(r.at("asked_hz")).c_str(), hz(r.at("highest_stable_hz")).c_str(), hz(r.at("unstable_side_hz")).c_str(),
                  r.at("kind").get<std::string>().c_str(), r.at("evaluations").get<int>(), hz(r.at("margin")).c_str());
    out += line;
  }
  return out;
}

}  // namespace softtune::app
