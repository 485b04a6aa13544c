#include "app/modes_app.h"

#include "app/simulate_app.h"
#include "codec/modes_codec.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "softtune/scene/linearise.h"
#include "softtune/scene/modal_tuning.h"

namespace softtune::app {

using namespace softtune::codec;
using namespace softtune::scene;
using nlohmann::json;

json run_modes(const json& request, const std::string& presets_dir) {
  ObjectReader r = read_object(request, "");
  const json scene_doc = requested_scene_document(r, request, presets_dir, {"mass_model", "at_s", "engine", "engine_settings"});
  const std::optional<MassModel> mass_model = read_mass_model(r);
  const SceneEngineChoice engine = read_request_engine(r);
  // The linearisation (scene/linearise.h) differentiates Box2D 2.4's own step: another engine's modes would be
  // Box2D's under its name, so it is refused rather than substituted.
  if (engine.backend->name != kDefaultSceneEngine) {
    throw invalid_field("engine", "modes are linearised in box2d_v2_4's step only: " + std::string(engine.backend->name) +
                                      "'s step is not linearised yet (simulate runs the scene in it)");
  }
  LinearisationOptions options;
  options.at_s = r.number("at_s");
  r.finish();
  Scene scene = decode_scene(scene_doc);
  if (auto e = check_linearisable(scene, options.at_s, "at_s")) throw_field_error(*e);
  const MassModel model = mass_model.value_or(scene.mass_model);

  StageList stages;
  stages.add(Stage::validate);
  if (scene.modal_tuning) {
    ModalTuningResult modal;
    Scene tuned;
    if (auto e = tune_modes(scene, model, modal, tuned, stages)) throw_field_error(*e);
    scene = std::move(tuned);
  }
  stages.add(Stage::settle);
  stages.add(Stage::linearise);
  LinearisedScene lin;
  if (auto e = linearise_scene(scene, model, options, lin)) throw_field_error(*e);
  stages.add(Stage::modes);
  const auto all = modes::modes_of(lin.model, modes::reduce(lin.model), lin.h);
  json out = linearisation_json(scene.name, lin, all, stages);
  out["engine"] = scene_engine_json(engine);
  return out;
}

}  // namespace softtune::app
