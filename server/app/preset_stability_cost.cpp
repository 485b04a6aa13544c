#include "app/preset_stability_cost.h"

#include <algorithm>

#include "app/scene_cost.h"

namespace softtune::app {

RequestCost preset_stability_cost(const scene::Scene& scene, const scene::PresetLimitSettings& settings) {
  scene::Scene run = scene;  // one twin-run world: Box2D bodies and joints for one run's length, nothing kept
  const int substeps = std::max(1, run.world.substeps);
  run.world.duration_s = static_cast<double>((settings.steps + substeps - 1) / substeps) / run.world.fps;
  run.probes.clear();
  run.oscillators.clear();
  run.expectations.clear();
  const double world_seconds = scene_cost(run, {}, "").cpu_seconds;
  const int searches = scene::search_count(scene);
  const int runs = searches * scene::max_evaluations_per_joint(settings);
  RequestCost cost;
  cost.cpu_seconds = runs * 2.0 * world_seconds;
  cost.peak_bytes = 2.0 * (4096.0 * static_cast<double>(scene.bodies.size() + scene.joints.size())) + 1024.0 * searches;
  cost.fields = {"preset"};
  cost.work = std::to_string(searches) + " searches x up to " + std::to_string(scene::max_evaluations_per_joint(settings)) +
              " twin runs x " + std::to_string(settings.steps) + " Box2D steps of " + std::to_string(scene.bodies.size()) +
              " bodies and " + std::to_string(scene.joints.size()) + " joints";
  return cost;
}

}  // namespace softtune::app
