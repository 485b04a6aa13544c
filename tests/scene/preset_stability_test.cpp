// Highest stable frequency per tuned joint of a preset, against physics: Box2D itself run just below and
// just above the reported limit, the 1-D chain's step matrix where the preset is that chain, and the talk's
// claim that one soft joint on the ground is stable at any frequency.
#include "softtune/scene/preset_stability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/chain_solvers.h"
#include "softtune/scene/box2d_scene.h"
#include "../presets_dir.h"

namespace softtune::scene {
namespace {

using test_support::kPresets;

Scene preset(const std::string& name) { return codec::decode_scene(app::load_preset(kPresets, name)); }

Scene with_frequency(Scene s, const std::vector<std::string>& joints, double hz) {
  for (JointSettings& j : s.joints) {
    if (std::find(joints.begin(), joints.end(), j.id) == joints.end()) continue;
    j.tuning->response_frames.reset();
    j.tuning->frequency_hz = hz;
  }
  return s;
}

// Largest body speed over `frames` frames of a plain run (no twin, no kick): the scene's own release is the
// only disturbance. Infinity when the state stops being finite.
double peak_speed(const Scene& scene, int frames, int from_frame = 0) {
  Box2DScene world(scene, scene.mass_model);
  double peak = 0.0;
  for (int f = 0; f < frames; ++f) {
    world.step_frame(f);
    for (const b2Body* b : world.bodies()) {
      const double v = b->GetLinearVelocity().Length();
      if (!std::isfinite(v)) return INFINITY;
      if (f >= from_frame) peak = std::max(peak, v);
    }
  }
  return peak;
}

PresetLimitSettings coarse() {
  PresetLimitSettings s;
  s.scan_points = 5;  // f h 0.01 .. 2, a factor 3.8 apart: fewer runs, the same bisected answer
  s.steps = 1200;     // half the default: this chain grows fast past its limit (1000x in 1841 steps at 1.004x)
  return s;
}

// Peak body speed of a plain 40 s Box2D run (no twin, no kick: the release from the unstretched springs is
// the only disturbance) over its first half second (the release) and over the rest (infinite when the state
// stops being finite).
struct Speeds {
  double release = 0.0, later = 0.0;
};
Speeds release_and_later(const Scene& scene, int frames = 2400) {
  return {peak_speed(scene, 30), peak_speed(scene, frames, 30)};
}

// The heavy weight (100 kg) hung straight below a light link (1 kg), one velocity iteration, warm starting:
// along the vertical it is exactly the 1-D chain of sequential_impulse.h, so Box2D's limit must be the
// step matrix's (chain_model(box2d_v2_4, 1 iteration, warm start, ratio 100)); and plain Box2D runs must be
// bounded at the stable side and blow up at 1.05x the unstable side.
TEST(PresetStability, HeavyOnLightHasAFiniteLimitThatBox2DConfirmsBelowAndAbove) {
  const Scene scene = preset("heavy_on_light");
  const PresetStabilityResult r = preset_stability_limits(scene, coarse());
  ASSERT_FALSE(r.error);
  ASSERT_EQ(r.joints.size(), 3u);  // upper, lower, both
  const JointStabilityLimit& all = r.joints[2];
  ASSERT_EQ(all.joint, kAllTunedJoints);
  ASSERT_EQ(all.limit.kind, LimitKind::found);
  ASSERT_TRUE(all.stable_side_hz && all.unstable_side_hz);
  EXPECT_LE(*all.unstable_side_hz / *all.stable_side_hz - 1.0, kLimitRelativeTolerance * 1.0001);

  const double h = r.h;
  const StabilityLimit model = find_stability_limit([&](double p) {
    return chain_spectral_radius(chain_step_matrix(chain_model(ChainSolver::box2d_v2_4, 1, true, 100.0, 2.0 * M_PI * p / h, 0.0, h)));
  }, log_scan(0.01, 2.0, 5));
  ASSERT_EQ(model.kind, LimitKind::found);
  EXPECT_NEAR(*all.stable_side_hz / (*model.stable_side / h), 1.0, 0.01);

  const Speeds below = release_and_later(with_frequency(scene, all.joints, *all.stable_side_hz));
  const Speeds above = release_and_later(with_frequency(scene, all.joints, 1.05 * *all.unstable_side_hz));
  EXPECT_LT(below.later, 1.5 * below.release) << "stable side " << *all.stable_side_hz << " Hz";
  EXPECT_GT(above.later, 3.0 * above.release) << "1.05 x unstable side " << *all.unstable_side_hz << " Hz";
  ASSERT_TRUE(all.margin);
  EXPECT_LT(*all.margin, 1.0);  // the preset as shipped (5 Hz) is inside its limit
}

TEST(PresetStability, OneSoftJointOnTheGroundHasNoLimitUpToTheCeiling) {
  const Scene scene = preset("stiff");
  const PresetStabilityResult r = preset_stability_limits(scene, coarse());
  ASSERT_FALSE(r.error);
  ASSERT_EQ(r.joints.size(), 1u);
  const JointStabilityLimit& l = r.joints[0];
  EXPECT_EQ(l.limit.kind, LimitKind::none_in_range);
  ASSERT_TRUE(l.highest_stable_hz);
  EXPECT_NEAR(*l.highest_stable_hz * r.h, coarse().highest_frequency_ratio, 1e-12);  // stable up to the ceiling
  EXPECT_EQ(l.limit.evaluations, coarse().scan_points);
  // Box2D at the ceiling (f h = 2), run plainly: bounded.
  EXPECT_LT(peak_speed(with_frequency(scene, l.joints, *l.highest_stable_hz), 2400), 1e3);
}

}  // namespace
}  // namespace softtune::scene
