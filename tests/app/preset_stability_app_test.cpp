// The preset search as the CLI and POST /api/v1/stability reach it: the request rules (a preset runs alone,
// named by a bounded string), the refusals before any world is built, and one soft joint on the ground
// answering "no limit inside the searched range" (the talk: the soft constraint alone, implicit Euler, is
// unconditionally stable).
#include "app/preset_stability_app.h"

#include <gtest/gtest.h>

#include "app/stability_app.h"
#include "codec/problem.h"
#include "codec/stability_codec.h"
#include "../presets_dir.h"

namespace softtune::app {
namespace {

using test_support::kPresets;

codec::Problem problem_of(const nlohmann::json& doc) {
  try {
    run_stability(codec::decode_stability_request(doc), kPresets);
  } catch (const codec::Problem& p) {
    return p;
  }
  ADD_FAILURE() << "no problem for " << doc.dump();
  return codec::Problem(0, "", "", "");
}

TEST(PresetStabilityApp, RequestRulesNameTheField) {
  EXPECT_EQ(problem_of({{"preset", "stiff"}, {"observe_steps", 1000}}).field, "observe_steps");
  EXPECT_EQ(problem_of({{"preset", ""}}).field, "preset");
  EXPECT_EQ(problem_of({{"preset", std::string(65, 'a')}}).field, "preset");
  EXPECT_EQ(problem_of({{"preset", 3}}).field, "preset");
  EXPECT_EQ(problem_of({{"preset", "no_such_preset"}}).status, 404);
  EXPECT_EQ(problem_of({{"preset", "vehicle"}}).field, "preset");  // modal-tuned
  // The scene engine rides beside the preset; an unknown one, or a setting it lacks, is named.
  EXPECT_EQ(problem_of({{"preset", "stiff"}, {"engine", "havok"}}).field, "engine");
  EXPECT_EQ(problem_of({{"preset", "stiff"}, {"engine", "bullet"}}).field, "engine");  // the search is Box2D's
  EXPECT_EQ(problem_of({{"preset", "stiff"}, {"engine_settings", {{"noSuchSetting", 1}}}}).field, "engine_settings.noSuchSetting");
}

// The bridge (11 tuned hangers and all of them together, 14 bodies) is priced over the 2 s budget and
// refused before it runs, naming `preset`.
TEST(PresetStabilityApp, OverBudgetPresetIsRefusedFirst) {
  const codec::Problem p = problem_of({{"preset", "bridge"}});
  EXPECT_EQ(p.status, 422);
  EXPECT_EQ(p.field, "preset");
  EXPECT_NE(std::string(p.what()).find("budget"), std::string::npos);
}

TEST(PresetStabilityApp, OneSoftJointOnTheGroundHasNoLimitInRange) {
  const nlohmann::json out = run_stability(codec::decode_stability_request({{"preset", "stiff"}}), kPresets);
  const nlohmann::json& rows = out.at("preset_limits").at("limits");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].at("joint"), "spring");
  EXPECT_EQ(rows[0].at("kind"), "none_in_range");
  EXPECT_TRUE(rows[0].at("unstable_side_hz").is_null());
  EXPECT_DOUBLE_EQ(rows[0].at("highest_stable_hz").get<double>(), out.at("preset_limits").at("searched_hz").at(1).get<double>());
  EXPECT_TRUE(out.at("summary").at("passed").get<bool>());
  EXPECT_NE(preset_limits_table(out).find("none_in_range"), std::string::npos);
}

}  // namespace
}  // namespace softtune::app
