#include "app/scene_tuning.h"

#include <algorithm>
#include <string_view>

#include "codec/problem.h"
#include "codec/tune_codec.h"

namespace softtune::app {

namespace {

using nlohmann::json;

// An item's designer fields (scene.h JointSettings::tuning, OscillatorSettings::tuning); an item with none
// of them is rigid, or copies a joint.
constexpr const char* kDesignerKeys[] = {"response_frames", "basis_fps", "frequency_hz", "oscillation", "damping_ratio"};

bool is_designer_tuned(const json& item) {
  return std::any_of(std::begin(kDesignerKeys), std::end(kDesignerKeys), [&item](const char* k) { return item.contains(k); });
}

// The tune codec reads the fields with their documented bounds; a unit mass stands in for the joints' own.
void check_tuning(const json& tuning) {
  if (!tuning.is_object()) throw codec::invalid_field("tuning", "must be an object with the designer fields of a tune request");
  json probe = json::object();
  for (const auto& [key, value] : tuning.items()) {
    const bool known = std::any_of(std::begin(kSceneTuningKeys), std::end(kSceneTuningKeys),
                                   [&name = key](const char* k) { return name == k; });
    if (!known) {
      throw codec::invalid_field("tuning." + key, "is not a tuning field (fps, substeps, response_frames or "
                                                  "frequency_hz, basis_fps, oscillation or damping_ratio, mode)");
    }
    probe[key] = value;
  }
  if (!probe.contains("response_frames") && !probe.contains("frequency_hz")) {
    throw codec::invalid_field("tuning.response_frames", "give the response speed: response_frames or frequency_hz");
  }
  if (!probe.contains("oscillation") && !probe.contains("damping_ratio")) {
    throw codec::invalid_field("tuning.oscillation", "give the oscillation: oscillation or damping_ratio");
  }
  probe["effective_mass"] = 1.0;
  try {
    codec::decode_tune_request(probe);
  } catch (const codec::Problem& p) {
    throw codec::Problem(p.status, p.title, p.field.empty() ? "tuning" : "tuning." + p.field, p.detail);
  }
}

void retune(json& item, const json& designer, const json* mode, bool keep_own_mode) {
  for (const char* k : kDesignerKeys) item.erase(k);
  for (const auto& [key, value] : designer.items()) item[key] = value;
  if (mode && !(keep_own_mode && item.contains("mode"))) item["mode"] = *mode;
}

}  // namespace

void apply_scene_tuning(json& scene_doc, const json& tuning) {
  check_tuning(tuning);
  json& world = scene_doc["world"];
  for (const char* k : {"fps", "substeps"}) {
    if (tuning.contains(k)) world[k] = tuning[k];
  }
  json designer = json::object();
  for (const char* k : kDesignerKeys) {
    if (tuning.contains(k)) designer[k] = tuning[k];
  }
  const json* mode = tuning.contains("mode") ? &tuning["mode"] : nullptr;
  for (const auto& [list, keep_own_mode] : {std::pair{"joints", false}, std::pair{"oscillators", true}}) {
    if (!scene_doc.contains(list)) continue;
    for (json& item : scene_doc[list]) {
      if (item.is_object() && is_designer_tuned(item)) retune(item, designer, mode, keep_own_mode);
    }
  }
  // A scene tuned by its modes (modal_tuning, docs/scenes.md): its targets ask what the designer asks, and
  // the solve takes the page's standard | exact (a target's own "mode" names its motion, and stays).
  if (scene_doc.contains("modal_tuning") && scene_doc["modal_tuning"].is_object()) {
    json& modal = scene_doc["modal_tuning"];
    if (mode) modal["mode"] = *mode;
    if (modal.contains("targets") && modal["targets"].is_array()) {
      for (json& target : modal["targets"]) {
        if (target.is_object()) retune(target, designer, nullptr, false);
      }
    }
  }
}

}  // namespace softtune::app
