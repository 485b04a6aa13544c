#pragma once
// Diagnostics every layer returns as data (docs/conventions.md, "Diagnostics are data"): the stages a computation ran, and the field a
// request was refused for. Warnings have their own header (warnings.h). Small on purpose, so code that
// only reports (the render pipeline, the scenes) need not include the tune header.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace softtune {

/// The stages a computation ran, in order; the response lists them so callers see what was left out.
enum class Stage : std::uint8_t {
  // tune
  validate, designer_mapping, effective_mass, softness, exact_softness, discrete_analysis, engine_export,
  engine_models,
  // scenes
  scene_setup, core_integrator, box2d_world, box2d_step, snapshots, response_fit, expectations,
  engine_world, engine_step,  ///< a scene's world and steps in an engine other than Box2D 2.4 (the answer's engine)
  // modes of a scene (modes.h, modal_tune.h, scene/linearise.h)
  settle, linearise, modes, modal_solve,
  // accuracy and stability
  accuracy_runs, box2d_distance_joint, recommendation, stability_sweep, sequential_impulse_chain,
  // rendering
  render, png_encode,
};
/// The stage's name in responses ("designer_mapping").
std::string_view stage_name(Stage s);

/// The stages that ran, in the order they ran. It grows with every add(), so no stage is ever dropped.
struct StageList {
  std::vector<Stage> items;
  void add(Stage s) { items.push_back(s); }
  /// Adds `other`'s stages after these (a preview: the simulation's, then the render's).
  void append(const StageList& other) { items.insert(items.end(), other.items.begin(), other.items.end()); }
  bool contains(Stage s) const {
    for (Stage item : items) if (item == s) return true;
    return false;
  }
};

/// A rejected field: `field` is its dotted path in the request ("constraint.body_a.mass"), `rule` says
/// what it must be.
struct FieldError {
  std::string field;
  std::string rule;
};

}  // namespace softtune
