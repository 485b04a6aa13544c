// The check's work estimate: frames x substeps x (bodies + joints) per run, counted from the scene before
// any step, and the refusal above the budget.
#include "app/check_cost.h"

#include <gtest/gtest.h>

#include "app/preset_store.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"

namespace softtune::app {
namespace {

TEST(CheckCost, WorkIsFramesTimesSubstepsTimesBodiesAndJointsPerRun) {
  // mouse: 3 s, one crate and one mouse joint, one mass model
  const scene::Scene mouse = codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, "mouse"));
  EXPECT_EQ(case_work(mouse, {60, 1}), 180.0 * 1 * 2);
  EXPECT_EQ(case_work(mouse, {144, 4}), 432.0 * 4 * 2);
  // buddhas: its box2d_reduced expectations need a second run
  const scene::Scene buddhas = codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, "buddhas"));
  const double per_run = scene::frame_count(buddhas.world) * static_cast<double>(buddhas.bodies.size() + buddhas.joints.size());
  EXPECT_EQ(case_work(buddhas, {60, 1}), 2 * per_run);

  CheckOptions o;
  o.fps = {30, 60};
  const std::vector<CheckInput> inputs = {{"mouse", load_preset(SOFTTUNE_PRESETS_DIR, "mouse"), std::nullopt}};
  EXPECT_EQ(check_work(inputs, o), 90.0 * 2 + 180.0 * 2);
  o.shard = {2, 2};  // the one preset is in shard 1
  EXPECT_EQ(check_work(inputs, o), 0.0);
}

TEST(CheckCost, AboveTheBudgetIsA422NamingTheFields) {
  EXPECT_NO_THROW(require_check_budget(kMaxCheckWork, kMaxCheckWork, "presets"));
  try {
    require_check_budget(2 * kMaxCheckWork, kMaxCheckWork, "presets, fps");
    FAIL() << "accepted";
  } catch (const codec::Problem& p) {
    EXPECT_EQ(p.status, 422);
    EXPECT_EQ(p.field, "presets, fps");
    EXPECT_NE(p.detail.find("1e+07 body-steps"), std::string::npos) << p.detail;
  }
}

}  // namespace
}  // namespace softtune::app
