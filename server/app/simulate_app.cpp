#include "app/simulate_app.h"

#include "app/check_app.h"
#include "app/scene_tuning.h"
#include "app/preset_store.h"
#include "app/scene_cost.h"
#include "codec/json_writer.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "codec/scene_engine_codec.h"
#include "codec/settings_codec.h"
#include "softtune/engines/scene_backends.h"
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
      try {
        validate_preset(scene_doc, load_schema(presets_dir), "scene");
      } catch (const Problem& p) {
        throw prefixed(p, "scene.");
      }
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

Problem prefixed(const Problem& p, const std::string& prefix) {
  Problem out(p.status, p.title, p.field.empty() ? prefix.substr(0, prefix.size() - 1) : prefix + p.field, p.detail);
  out.extensions = p.extensions;
  return out;
}

Scene decode_requested_scene(const json& scene_doc, const std::string& prefix) {
  try {
    return decode_scene(scene_doc);
  } catch (const Problem& p) {
    if (prefix.empty()) throw;
    throw prefixed(p, prefix);
  }
}

SceneEngineChoice read_request_engine(ObjectReader& r) { return read_scene_engine(r, engines::scene_backends()); }

json run_simulate(const json& request, const std::string& presets_dir) {
  ObjectReader r = read_object(request, "");
  const json scene_doc = requested_scene_document(r, request, presets_dir, kSceneRunOptions);
  RunOptions options;
  options.mass_model = read_mass_model(r);
  apply_scene_engine(read_request_engine(r), options);
  options.record_frames = read_bool(r, "frames", false);
  if (auto stride = r.integer("frame_stride")) {
    if (*stride < 1 || *stride > kMaxFrameStride) {
      throw invalid_field("frame_stride", "must be an integer in [1, " + std::to_string(kMaxFrameStride) + "]");
    }
    options.frame_stride = static_cast<int>(*stride);
  }
  r.finish();
  const std::string prefix = request.contains("scene") ? "scene." : "";
  const Scene scene = decode_requested_scene(scene_doc, prefix);
  require_within_budget(scene_cost(scene, options, prefix));
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

json scene_engines_index() {
  json list = json::array();
  for (const SceneBackend* b : engines::scene_backends()) {
    json settings = json::array();
    for (const engines::SettingSpec& spec : b->settings) {
      json s = {{"name", spec.name}, {"min", spec.min}, {"max", spec.max}, {"integer", spec.integer}};
      if (is_switch_setting(spec)) {
        s["default"] = spec.default_value != 0.0;
      } else if (!spec.choices.empty()) {
        s["default"] = spec.choices[static_cast<std::size_t>(spec.default_value)];
        s["choices"] = std::vector<std::string>(spec.choices.begin(), spec.choices.end());
      } else {
        s["default"] = spec.default_value;
      }
      if (!spec.unit.empty()) s["unit"] = spec.unit;
      if (!spec.meaning.empty()) s["meaning"] = spec.meaning;
      settings.push_back(std::move(s));
    }
    list.push_back({{"name", b->name}, {"version", b->version}, {"default", b->name == kDefaultSceneEngine},
                    {"settings", std::move(settings)}});
  }
  return {{"engines", std::move(list)}};
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
