// The preset search's price: it counts what the search really runs (no search takes more twin runs than the
// price assumes, and there is one search per tuned joint plus one for all of them), it grows with the run
// length, and it lets the small presets through while the bridge is refused.
#include "app/preset_stability_cost.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "codec/scene_codec.h"

namespace softtune::app {
namespace {

scene::Scene preset(const std::string& name) { return codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, name)); }

TEST(PresetStabilityCost, CountsTheRunsTheSearchMakes) {
  const scene::Scene s = preset("heavy_on_light");
  scene::PresetLimitSettings settings;
  settings.steps = 600;  // short runs: the count of runs, not their length, is under test
  const scene::PresetStabilityResult result = scene::preset_stability_limits(s, settings);
  ASSERT_FALSE(result.error);
  EXPECT_EQ(static_cast<int>(result.joints.size()), scene::search_count(s));
  for (const auto& j : result.joints) EXPECT_LE(j.limit.evaluations, scene::max_evaluations_per_joint(settings)) << j.joint;
  const RequestCost cost = preset_stability_cost(s, settings);
  EXPECT_EQ(cost.fields, std::vector<std::string>{"preset"});
  settings.steps = 2400;
  EXPECT_NEAR(preset_stability_cost(s, settings).cpu_seconds / cost.cpu_seconds, 4.0, 0.1);
}

TEST(PresetStabilityCost, SmallPresetsFitTheBudgetAndTheBridgeDoesNot) {
  const scene::PresetLimitSettings defaults;
  EXPECT_NO_THROW(require_within_budget(preset_stability_cost(preset("heavy_on_light"), defaults)));
  EXPECT_NO_THROW(require_within_budget(preset_stability_cost(preset("stiff"), defaults)));
  EXPECT_ANY_THROW(require_within_budget(preset_stability_cost(preset("bridge"), defaults)));
}

}  // namespace
}  // namespace softtune::app
