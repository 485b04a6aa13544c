#include "softtune/diagnostics.h"

namespace softtune {

std::string_view stage_name(Stage s) {
  switch (s) {
    case Stage::validate: return "validate";
    case Stage::designer_mapping: return "designer_mapping";
    case Stage::effective_mass: return "effective_mass";
    case Stage::softness: return "softness";
    case Stage::exact_softness: return "exact_softness";
    case Stage::discrete_analysis: return "discrete_analysis";
    case Stage::engine_export: return "engine_export";
    case Stage::engine_models: return "engine_models";
    case Stage::accuracy_runs: return "accuracy_runs";
    case Stage::box2d_distance_joint: return "box2d_distance_joint";
    case Stage::recommendation: return "recommendation";
    case Stage::stability_sweep: return "stability_sweep";
    case Stage::sequential_impulse_chain: return "sequential_impulse_chain";
    case Stage::scene_setup: return "scene_setup";
    case Stage::core_integrator: return "core_integrator";
    case Stage::box2d_world: return "box2d_world";
    case Stage::box2d_step: return "box2d_step";
    case Stage::engine_world: return "engine_world";
    case Stage::engine_step: return "engine_step";
    case Stage::snapshots: return "snapshots";
    case Stage::response_fit: return "response_fit";
    case Stage::expectations: return "expectations";
    case Stage::settle: return "settle";
    case Stage::linearise: return "linearise";
    case Stage::modes: return "modes";
    case Stage::modal_solve: return "modal_solve";
    case Stage::render: return "render";
    case Stage::png_encode: return "png_encode";
  }
  return "unknown";
}

}  // namespace softtune
