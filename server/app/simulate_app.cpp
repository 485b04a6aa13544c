#include "app/simulate_app.h"

#include "app/check_app.h"
#include "app/scene_tuning.h"
#include "app/preset_store.h"
#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "softtune/scene/expectations.h"
#include "softtune/scene/runner.h"

namespace softtune::app {

using namespace softtune::codec;  // the codec is this layer's JSON vocabulary
using namespace softtune::scene;
using nlohmann::json;

json requested_scene_document(ObjectReader& r, const json& request, const std::string& presets_dir,
                              std::initializer_list<const char*> run_options) {
  if (r.has("preset") || r.has("scene")) {
    if (r.has("preset") && r.has("scene")) throw invalid_field("scene", "give either preset or scene, not both");
    json scene_doc;
    if (auto name = r.string("preset")) {
      scene_doc = load_preset(presets_dir, *name);
    } else {
      scene_doc = *r.raw("scene");
      // The schema would name the scene's root "" (its own JSON pointer); the request's field is "scene".
      if (!scene_doc.is_object()) throw invalid_field("scene", "must be a JSON object (a scene, as in presets/*.json)");
      validate_preset(scene_doc, load_schema(presets_dir), "scene");
    }
    if (const json* tuning = r.raw("tuning")) apply_scene_tuning(scene_doc, *tuning);
    return scene_doc;
  }
  // A bare scene: every key belongs to it, except the run options.
  json scene_doc = request;
  for (const char* option : run_options) scene_doc.erase(option);
  validate_preset(scene_doc, load_schema(presets_dir), "request");
  for (auto it = scene_doc.begin(); it != scene_doc.end(); ++it) r.raw(it.key());
  return scene_doc;
}

json run_simulate(const json& request, const std::string& presets_dir) {
  ObjectReader r = read_object(request, "");
  const json scene_doc = requested_scene_document(r, request, presets_dir, {"frames", "frame_stride"});
  RunOptions options;
  options.mass_model = read_mass_model(r);
  options.record_frames = read_bool(r, "frames", false);
  if (auto stride = r.integer("frame_stride")) {
    if (*stride < 1 || *stride > kMaxFrameStride) {
      throw invalid_field("frame_stride", "must be an integer in [1, " + std::to_string(kMaxFrameStride) + "]");
    }
    options.frame_stride = static_cast<int>(*stride);
  }
  r.finish();
  const Scene scene = decode_scene(scene_doc);
  return encode_scene_result(scene, run_scene(scene, options));
}

json run_simulate(const json& request) { return run_simulate(request, resolve_presets_dir()); }

json presets_index(const std::string& presets_dir) {
  json list = json::array();
  for (const std::string& name : list_presets(presets_dir)) {
    // One broken file must not hide the others: it is listed with the problem that refuses it.
    try {
      const json preset = load_preset(presets_dir, name);
      list.push_back({{"name", name}, {"description", preset.value("description", "")}, {"valid", true}});
    } catch (const Problem& p) {
      list.push_back({{"name", name}, {"description", ""}, {"valid", false}, {"problem", problem_json(p)}});
    }
  }
  return {{"presets", std::move(list)}};
}

json preset_document(const std::string& presets_dir, const std::string& name) { return load_preset(presets_dir, name); }

json check_preset(const json& preset) {
  const Scene scene = decode_scene(preset);
  const CheckResult check = check_scene(scene);
  for (const SceneResult& run : check.runs) {
    if (run.error) throw_field_error(*run.error);
  }
  return {{"name", scene.name}, {"passed", check.passed}, {"stages", stages_json(check.runs.front().stages)},
          {"expectations", expectations_json(check)}};
}

}  // namespace softtune::app
