// The A/B ghost (server/app/ghost_tuning.cpp, scene_frames add_ghost): a second tuning on every tuned
// joint, its errors named under `ghost.`, and its bodies drawn translucent over the first run.
#include "app/ghost_tuning.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/preset_store.h"
#include "app/scene_frames.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "softtune/scene/runner.h"

namespace softtune::app {
namespace {

using nlohmann::json;

scene::Scene vehicle() { return codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, "vehicle_per_spring")); }

std::string field_of(const scene::Scene& s, const json& ghost) {
  try {
    ghost_scene(s, ghost);
  } catch (const codec::Problem& p) {
    return p.field;
  }
  return "";
}

TEST(GhostTuning, ReplacesTheDesignerFieldsOfEveryTunedJoint) {
  const scene::Scene a = vehicle();
  const scene::Scene b = ghost_scene(a, {{"frequency_hz", 1.5}, {"damping_ratio", 0.1}, {"mode", "exact"}});
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t j = 0; j < b.joints.size(); ++j) {
    ASSERT_TRUE(b.joints[j].tuning);
    EXPECT_FALSE(b.joints[j].tuning->response_frames);
    EXPECT_EQ(b.joints[j].tuning->frequency_hz, 1.5);
    EXPECT_EQ(b.joints[j].tuning->damping_ratio, 0.1);
    EXPECT_FALSE(b.joints[j].tuning->oscillation);
    EXPECT_EQ(b.joints[j].tuning->mode, SoftMode::exact);
  }
  // A softer suspension: the runner's requested frequency follows the ghost's.
  scene::RunOptions options;
  options.record_frames = true;
  options.frame_stride = 30;
  const scene::SceneResult rb = scene::run_scene(b, options);
  ASSERT_FALSE(rb.error);
  EXPECT_NEAR(rb.joints[0].requested_frequency_hz, 1.5, 1e-12);
  // Drawn over a frame of the first run: one ghost per moving body, one ghost spring per tuned joint.
  const scene::SceneResult ra = scene::run_scene(a, options);
  render::DrawFrame f = scene_frame(a, ra.snapshots, 3);
  const std::size_t polygons = f.polygons.size(), circles = f.circles.size(), springs = f.springs.size();
  add_ghost(f, b, rb.snapshots[3]);
  int moving_polygons = 0, moving_circles = 0;
  for (const scene::BodySettings& body : b.bodies) {
    if (body.is_static) continue;
    (body.shape.kind == scene::ShapeKind::circle ? moving_circles : moving_polygons) += 1;
  }
  EXPECT_EQ(f.polygons.size() - polygons, static_cast<std::size_t>(moving_polygons));
  EXPECT_EQ(f.circles.size() - circles, static_cast<std::size_t>(moving_circles));
  ASSERT_EQ(f.springs.size() - springs, 2u);
  EXPECT_TRUE(f.springs.back().ghost);
  EXPECT_EQ(f.polygons.back().role, render::Role::ghost);
}

TEST(GhostTuning, BadFieldsAreNamedUnderGhost) {
  const scene::Scene a = vehicle();
  EXPECT_EQ(field_of(a, {{"response_frames", -3}}), "ghost.response_frames");
  EXPECT_EQ(field_of(a, {{"bogus", 1}}), "ghost.bogus");
  EXPECT_EQ(field_of(a, {{"response_frames", 10}, {"frequency_hz", 2}}), "ghost.frequency_hz");
  EXPECT_EQ(field_of(a, {{"oscillation", "wobbly"}}), "ghost.oscillation");
  EXPECT_EQ(field_of(a, json::array()), "ghost");
  const scene::Scene chain = codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, "chain"));
  EXPECT_EQ(field_of(chain, {{"response_frames", 10}}), "ghost");
}

// On a modally tuned preset the ghost is its own solve: its mode target takes the ghost's request, and the
// ghost's run measures the chassis heave there (40 frames at 60 fps = 1.5 Hz), not the first run's 3 Hz.
TEST(GhostTuning, AModalSceneSolvesTheGhostsOwnTarget) {
  const scene::Scene a = codec::decode_scene(load_preset(SOFTTUNE_PRESETS_DIR, "vehicle"));
  const scene::Scene b = ghost_scene(a, {{"response_frames", 40}, {"oscillation", "some"}, {"mode", "exact"}});
  ASSERT_TRUE(b.modal_tuning);
  EXPECT_EQ(*b.modal_tuning->targets[0].tuning.response_frames, 40.0);
  const scene::SceneResult run_a = scene::run_scene(a), run_b = scene::run_scene(b);
  ASSERT_FALSE(run_a.error);
  ASSERT_FALSE(run_b.error);
  ASSERT_TRUE(run_b.modal_tuning);
  EXPECT_NEAR(run_b.modal_tuning->targets[0].requested_frequency_hz, 1.5, 1e-12);
  EXPECT_LT(run_b.modal_tuning->groups[0].stiffness, 0.5 * run_a.modal_tuning->groups[0].stiffness);
  for (const scene::ProbeResult& p : run_b.probes) {
    if (p.id != "heave") continue;
    ASSERT_TRUE(p.measured.frequency_hz);
    EXPECT_NEAR(*p.measured.frequency_hz / 1.5, 1.0, 0.03);
  }
}

}  // namespace
}  // namespace softtune::app
