// The scene runner against the physics: Box2D's soft joint is implicit Euler, runs are deterministic, the 1-D
// oscillator never creates a Box2D world, snapshots come only when asked, and explicit integrators blow up
// where the soft constraint does not.
#include "softtune/scene/runner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene_builders.h"

namespace softtune::scene {
namespace {

using namespace test;

TEST(SceneRunner, Box2DSoftJointIsTheCoreSoftStep) {
  for (double f : {2.0, 20.0}) {
    const SceneResult r = run_scene(hanging_weight(f, Oscillation::free));
    ASSERT_FALSE(r.error);
    const auto& box2d = r.probes[0].value;
    const auto& core = r.probes[1].value;
    ASSERT_EQ(box2d.size(), core.size());
    for (std::size_t n = 0; n < core.size(); ++n) {
      // The body starts 0.1 m stretched below rest: its displacement is -0.1 + (0.1 - x_core) measured upward.
      EXPECT_NEAR(-box2d[n], 0.1 - core[n], 2e-6) << f << " Hz, frame " << n;
    }
  }
}

// A joint as typed (no tuning): Box2D runs exactly the typed k, c -- implicit Euler on (m, k, c), written out
// here: v' = (m v - h k x) / (m + h c + h^2 k), x' = x + h v' -- and nothing is asked of it.
TEST(SceneRunner, TypedJointRunsTheTypedValues) {
  Scene s = hanging_weight(2.0, Oscillation::free);
  s.oscillators.clear();
  s.probes.resize(1);
  const double k = 300.0, c = 4.0, m = 1.0, h = 1.0 / 60.0;
  s.joints[0].tuning.reset();
  s.joints[0].typed = TypedSpring{k, c};
  const SceneResult r = run_scene(s);
  ASSERT_FALSE(r.error);
  EXPECT_TRUE(r.joints[0].typed);
  EXPECT_FALSE(r.joints[0].tuned);
  EXPECT_FALSE(r.probes[0].requested_frequency_hz);
  double x = 0.1, v = 0.0;  // stretched 0.1 m below rest, displacement measured upward
  for (std::size_t n = 0; n < r.probes[0].value.size(); ++n) {
    EXPECT_NEAR(-r.probes[0].value[n], 0.1 - x, 2e-6) << "frame " << n;
    v = (m * v - h * k * x) / (m + h * c + h * h * k);
    x += h * v;
  }
}

TEST(SceneRunner, SameSceneTwiceGivesIdenticalTrajectories) {
  const Scene s = buddhas({0.3, 0.8});
  const SceneResult a = run_scene(s), b = run_scene(s);
  ASSERT_EQ(a.probes.size(), b.probes.size());
  for (std::size_t i = 0; i < a.probes.size(); ++i) EXPECT_EQ(a.probes[i].value, b.probes[i].value);
}

TEST(SceneRunner, TheOscillatorRunsWithoutBox2D) {
  Scene s;
  s.name = "oscillator";
  OscillatorSettings o;
  o.id = "x";
  o.effective_mass = 2.0;
  o.method = Method::soft_exact;
  o.tuning = designer(30, Oscillation::some, SoftMode::exact);
  s.oscillators.push_back(o);
  s.probes.push_back(probe("x", ProbeKind::oscillator, "x"));
  const SceneResult r = run_scene(s);
  ASSERT_FALSE(r.error);
  EXPECT_TRUE(r.stages.contains(Stage::core_integrator));
  EXPECT_FALSE(r.stages.contains(Stage::box2d_world));
  EXPECT_FALSE(r.stages.contains(Stage::box2d_step));
  EXPECT_FALSE(r.stages.contains(Stage::snapshots));
  EXPECT_NEAR(*r.probes[0].measured.frequency_hz, 2.0, 1e-9);
}

TEST(SceneRunner, SnapshotsOnlyWhenAsked) {
  const Scene s = buddhas({0.5});
  EXPECT_TRUE(run_scene(s).snapshots.empty());
  RunOptions options;
  options.record_frames = true;
  options.frame_stride = 10;
  const SceneResult r = run_scene(s, options);
  EXPECT_TRUE(r.stages.contains(Stage::snapshots));
  ASSERT_EQ(r.snapshots.size(), static_cast<std::size_t>(r.frames / 10 + 1));
  const BodySnapshot& plank = r.snapshots.front().bodies[1];
  ASSERT_EQ(plank.vertices.size(), 4u);
  for (const auto& v : plank.vertices) EXPECT_NEAR((v - Eigen::Vector2d(0, 0)).norm(), std::hypot(1.0, 0.1), 1e-6);
  const JointSnapshot& hanger = r.snapshots.front().joints[0];
  EXPECT_NEAR(*hanger.rest_length, 2.98, 1e-6);
  EXPECT_NEAR(hanger.current_length, 3.0, 1e-6);
}

TEST(SceneRunner, ExplicitAndSemiImplicitBlowUpWhereTheSoftConstraintDoesNot) {
  Scene s = hanging_weight(20.0, Oscillation::free);  // omega h = 2.09 at 60 fps
  for (Method m : {Method::explicit_euler, Method::semi_implicit_euler}) {
    OscillatorSettings o = s.oscillators.front();
    o.id = std::string(method_name(m));
    o.method = m;
    s.oscillators.push_back(o);
    s.probes.push_back(probe(o.id, ProbeKind::oscillator, o.id));
  }
  const SceneResult r = run_scene(s);
  ASSERT_FALSE(r.error);
  EXPECT_TRUE(r.finite);
  EXPECT_LE(r.probes[1].max_abs_value, 0.1 + 1e-12);  // soft: never beyond its start
  EXPECT_FALSE(r.probes[1].diverged);
  EXPECT_TRUE(r.probes[2].diverged);
  EXPECT_TRUE(r.probes[3].diverged);
  for (const ProbeResult& p : r.probes) {
    for (double v : p.value) EXPECT_TRUE(std::isfinite(v));
  }
}

}  // namespace
}  // namespace softtune::scene
