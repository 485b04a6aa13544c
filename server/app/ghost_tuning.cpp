#include "app/ghost_tuning.h"

#include "codec/json_reader.h"
#include "codec/problem.h"
#include "softtune/validation.h"

namespace softtune::app {

scene::Scene ghost_scene(const scene::Scene& scene, const nlohmann::json& ghost) {
  using codec::invalid_field;
  codec::ObjectReader r = codec::read_object(ghost, "ghost");
  const auto response_frames = r.number("response_frames");
  const auto frequency_hz = r.number("frequency_hz");
  const auto basis_fps = r.number("basis_fps");
  const auto oscillation = r.choice("oscillation", {"free", "some", "none"});
  const auto damping_ratio = r.number("damping_ratio");
  const auto mode = r.choice("mode", {"standard", "exact"});
  r.finish();
  if (response_frames && frequency_hz) throw invalid_field("ghost.frequency_hz", "give response_frames or frequency_hz, not both");
  if (oscillation && damping_ratio) throw invalid_field("ghost.damping_ratio", "give oscillation or damping_ratio, not both");
  scene::Scene out = scene;
  // One designer request retuned as the ghost asks, checked as the runner will (fps, substeps, a mass).
  auto retune = [&](TuneRequest& t) {
    if (response_frames || frequency_hz) t.response_frames = response_frames, t.frequency_hz = frequency_hz;
    if (basis_fps) t.basis_fps = *basis_fps;
    if (oscillation || damping_ratio) {
      t.oscillation = oscillation ? std::optional(static_cast<Oscillation>(*oscillation)) : std::nullopt;
      t.damping_ratio = damping_ratio;
    }
    if (mode) t.mode = static_cast<SoftMode>(*mode);
    TuneRequest check = t;
    check.fps = scene.world.fps;
    check.substeps = scene.world.substeps;
    if (!check.effective_mass && !check.constraint) check.effective_mass = 1.0;
    if (auto e = validate_tune_request(check)) throw invalid_field("ghost." + e->field, e->rule);
  };
  bool any = false;
  for (scene::JointSettings& j : out.joints) {
    if (!j.tuning) continue;
    any = true;
    retune(*j.tuning);
  }
  if (!any) throw invalid_field("ghost", "the scene has no tuned joint to give a second tuning");
  // A scene tuned by its modes: the ghost's request is its targets' (solved again for the ghost), and its
  // mode the solve's, as apply_scene_tuning does for the page's own tuning.
  if (out.modal_tuning) {
    for (scene::ModeTargetSettings& target : out.modal_tuning->targets) retune(target.tuning);
    if (mode) out.modal_tuning->mode = static_cast<SoftMode>(*mode);
  }
  return out;
}

}  // namespace softtune::app
