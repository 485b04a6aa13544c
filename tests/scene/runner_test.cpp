// The scene runner against the physics: a single soft joint on a free body is the 1-D oscillator of m_eff,
// Box2D's K is the core's K, Box2D's soft joint is implicit Euler, runs are deterministic, and the 1-D
// oscillator never creates a Box2D world.
#include "softtune/scene/runner.h"

#include <gtest/gtest.h>

#include <cmath>

#include "softtune/discrete_analysis.h"
#include "softtune/scene/box2d_scene.h"
#include "softtune/scene/expectations.h"

namespace softtune::scene {
namespace {

TuneRequest designer(double frames, Oscillation level, SoftMode mode = SoftMode::standard) {
  TuneRequest q;
  q.response_frames = frames;
  q.oscillation = level;
  q.mode = mode;
  return q;
}

BodySettings box(const std::string& id, double w, double h, Eigen::Vector2d at, std::optional<double> mass, bool is_static = false) {
  BodySettings b;
  b.id = id;
  b.shape.width = w;
  b.shape.height = h;
  b.position = at;
  b.mass = mass;
  b.is_static = is_static;
  return b;
}

JointSettings joint(const std::string& id, JointKind kind, const std::string& a, const std::string& b, std::optional<TuneRequest> tuning) {
  JointSettings j;
  j.id = id;
  j.kind = kind;
  j.body_a = a;
  j.body_b = b;
  j.tuning = tuning;
  return j;
}

// A probe reading `target`: a body, joint or oscillator id depending on the kind.
ProbeSettings probe(const std::string& id, ProbeKind kind, const std::string& target) {
  ProbeSettings p;
  p.id = id;
  p.kind = kind;
  if (kind == ProbeKind::displacement || kind == ProbeKind::angle) p.body = target;
  else if (kind == ProbeKind::oscillator) p.oscillator = target;
  else p.joint = target;
  return p;
}

// The talk's Buddhas: identical 2 m x 0.2 m, 4 kg planks in zero gravity, each hung at `offsets` along it.
Scene buddhas(const std::vector<double>& offsets) {
  Scene s;
  s.name = "buddhas";
  s.world.gravity = {0, 0};
  s.world.duration_s = 4.0;
  s.bodies.push_back(box("ceiling", 30, 0.2, {7.5, 3.1}, std::nullopt, true));
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    const double x = 5.0 * i;
    s.bodies.push_back(box("plank" + std::to_string(i), 2.0, 0.2, {x, 0}, 4.0));
    JointSettings j = joint("hanger" + std::to_string(i), JointKind::distance, "ceiling", "plank" + std::to_string(i),
                            designer(60, Oscillation::some, SoftMode::exact));
    j.anchor_a = {x + offsets[i], 3.0};
    j.anchor_b = {x + offsets[i], 0.0};
    j.length = 2.98;
    s.joints.push_back(j);
    s.probes.push_back(probe(j.id, ProbeKind::joint_length, j.id));
  }
  return s;
}

// m_eff of a plank (mass m, L x H) held at r from its centre, perpendicular to it: 1 / (1/m + r^2 / I).
double plank_effective_mass(double m, double l, double h, double r) { return 1.0 / (1.0 / m + r * r / (m * (l * l + h * h) / 12.0)); }

TEST(SceneRunner, BuddhasLandOnTheRequestWithTheEffectiveMass) {
  const std::vector<double> offsets = {0.0, 0.4, 0.7, 0.95};
  const SceneResult r = run_scene(buddhas(offsets));
  ASSERT_FALSE(r.error);
  for (std::size_t i = 0; i < offsets.size(); ++i) {
    EXPECT_NEAR(r.joints[i].effective_mass, plank_effective_mass(4.0, 2.0, 0.2, offsets[i]), 1e-4) << i;
    ASSERT_TRUE(r.probes[i].frequency_error) << i;
    EXPECT_LT(std::abs(*r.probes[i].frequency_error), 0.03) << i;
    EXPECT_LT(std::abs(*r.probes[i].damping_ratio_error), 0.03) << i;
  }
}

TEST(SceneRunner, Box2DReducedMassMissesOffCentrePlanksAsImplicitEulerOnTheTrueMassPredicts) {
  const std::vector<double> offsets = {0.0, 0.7, 0.95};
  const SceneResult r = run_scene(buddhas(offsets), RunOptions{MassModel::box2d_reduced});
  ASSERT_FALSE(r.error);
  EXPECT_LT(std::abs(*r.probes[0].frequency_error), 0.03);
  for (std::size_t i = 1; i < offsets.size(); ++i) {
    // k, c were computed for m = 4 kg but the plank resists with m_eff: the joint is implicit Euler on
    // (m_eff, k, c), whose discrete poles give the frequency Box2D must show (roughly f sqrt(m / m_eff)).
    const JointTuning& t = r.joints[i];
    EXPECT_DOUBLE_EQ(t.model_mass, 4.0);
    StepModel model;
    model.h = r.h;
    model.spring = {t.effective_mass, t.stiffness, t.damping};
    std::complex<double> z1, z2;
    eigenvalues_2x2(step_matrix(Method::implicit_euler, model), z1, z2);
    double f = 0.0, zeta = 0.0;
    ASSERT_TRUE(achieved_from_poles(z1, z2, r.h, f, zeta));
    EXPECT_NEAR(*r.probes[i].measured.frequency_hz / f, 1.0, 0.01) << i;
    EXPECT_NEAR(*r.probes[i].measured.damping_ratio, zeta, 0.01) << i;
    EXPECT_GT(*r.probes[i].frequency_error, 0.3) << i;
  }
}

// The talk's mental experiment, done in Box2D itself: equal and opposite unit impulses at the anchors, relative
// anchor velocity along the axis = K. Box2D's answer must be the core's 1 / m_eff for every joint kind.
double box2d_unit_impulse(b2Body* a, b2Body* b, b2Vec2 pa, b2Vec2 pb, b2Vec2 axis) {
  for (b2Body* body : {a, b}) {
    body->SetLinearVelocity(b2Vec2_zero);
    body->SetAngularVelocity(0.0f);
  }
  a->ApplyLinearImpulse(-axis, pa, true);
  b->ApplyLinearImpulse(axis, pb, true);
  return b2Dot(b->GetLinearVelocityFromWorldPoint(pb) - a->GetLinearVelocityFromWorldPoint(pa), axis);
}

TEST(SceneRunner, Box2DsOwnKAgreesWithTheCoreForEveryJointKind) {
  Scene s;
  s.name = "k";
  s.world.gravity = {0, 0};
  s.bodies.push_back(box("chassis", 3.0, 0.5, {0, 1}, 120.0));
  BodySettings wheel;
  wheel.id = "wheel";
  wheel.shape.kind = ShapeKind::circle;
  wheel.shape.radius = 0.4;
  wheel.mass = 15.0;
  wheel.position = {-1.1, 0.4};
  s.bodies.push_back(wheel);
  s.bodies.push_back(box("crate", 1.0, 0.6, {5, 0}, 5.0));
  s.bodies.push_back(box("arm", 2.0, 0.3, {9, 0}, 3.0));
  s.bodies.push_back(box("base", 1.0, 1.0, {11, 0}, 7.0));
  JointSettings w = joint("suspension", JointKind::wheel, "chassis", "wheel", designer(20, Oscillation::some));
  w.anchor_b = {-1.1, 0.4};
  w.axis = {0.3, 1.0};
  JointSettings d = joint("rope", JointKind::distance, "chassis", "crate", designer(30, Oscillation::some));
  d.anchor_a = {1.2, 1.1};
  d.anchor_b = {4.7, 0.25};
  JointSettings m = joint("drag", JointKind::mouse, "", "crate", designer(30, Oscillation::none));
  m.anchor_b = {5.4, -0.2};
  m.target = {6.0, 1.0};
  JointSettings weld = joint("weld", JointKind::weld, "arm", "base", designer(30, Oscillation::some));
  weld.anchor_a = {10.2, 0};
  s.joints = {w, d, m, weld};
  ASSERT_FALSE(validate_scene(s));
  Box2DScene world(s, MassModel::effective);
  ASSERT_FALSE(world.error());
  auto body = [&](int i) { return world.bodies()[i]; };
  auto v = [](const Eigen::Vector2d& x) { return b2Vec2(static_cast<float>(x.x()), static_cast<float>(x.y())); };

  const b2Vec2 axis_w = v(w.axis.normalized());
  EXPECT_NEAR(box2d_unit_impulse(body(0), body(1), v(w.anchor_b), v(w.anchor_b), axis_w) * world.tunings()[0].effective_mass, 1.0, 1e-5);
  const b2Vec2 axis_d = v((d.anchor_b - d.anchor_a).normalized());
  EXPECT_NEAR(box2d_unit_impulse(body(0), body(2), v(d.anchor_a), v(d.anchor_b), axis_d) * world.tunings()[1].effective_mass, 1.0, 1e-5);
  // The mouse joint pulls against a fixed target: impulse on the crate alone.
  const b2Vec2 axis_m = v((m.target - m.anchor_b).normalized());
  body(2)->SetLinearVelocity(b2Vec2_zero);
  body(2)->SetAngularVelocity(0.0f);
  body(2)->ApplyLinearImpulse(axis_m, v(m.anchor_b), true);
  EXPECT_NEAR(b2Dot(body(2)->GetLinearVelocityFromWorldPoint(v(m.anchor_b)), axis_m) * world.tunings()[2].effective_mass, 1.0, 1e-5);
  // Weld: angular, unit angular impulses.
  body(3)->SetAngularVelocity(0.0f);
  body(4)->SetAngularVelocity(0.0f);
  body(3)->ApplyAngularImpulse(-1.0f, true);
  body(4)->ApplyAngularImpulse(1.0f, true);
  EXPECT_TRUE(world.tunings()[3].angular);
  EXPECT_NEAR((body(4)->GetAngularVelocity() - body(3)->GetAngularVelocity()) * world.tunings()[3].effective_mass, 1.0, 1e-5);
  // k = m_eff omega^2 reached Box2D.
  EXPECT_NEAR(static_cast<b2WheelJoint*>(world.joints()[0])->GetStiffness(), world.tunings()[0].stiffness, 1e-3 * world.tunings()[0].stiffness);
}

// One stiff soft distance joint, fixed rotation: the body moves exactly like the core's soft step (implicit
// Euler) on the same (m_eff, k, c) -- Box2D works in float, so to float precision.
Scene hanging_weight(double frequency_hz, Oscillation level) {
  Scene s;
  s.name = "weight";
  s.world.gravity = {0, 0};
  s.world.duration_s = 1.0;
  s.bodies.push_back(box("anchor", 0.5, 0.2, {0, 2}, std::nullopt, true));
  BodySettings weight = box("weight", 0.3, 0.3, {0, 0.9}, 1.0);
  weight.fixed_rotation = true;
  s.bodies.push_back(weight);
  TuneRequest q;
  q.frequency_hz = frequency_hz;
  q.oscillation = level;
  JointSettings j = joint("spring", JointKind::distance, "anchor", "weight", q);
  j.anchor_a = {0, 2};
  j.anchor_b = {0, 0.9};
  j.length = 1.0;
  s.joints.push_back(j);
  OscillatorSettings o;
  o.id = "soft";
  o.method = Method::soft;
  o.joint = "spring";
  o.initial_displacement = 0.1;
  s.oscillators.push_back(o);
  ProbeSettings body_probe = probe("body", ProbeKind::displacement, "weight");
  body_probe.axis = {0, -1};
  s.probes = {body_probe, probe("core", ProbeKind::oscillator, "soft")};
  return s;
}

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

TEST(SceneValidation, NamesTheFieldAndTheRule) {
  Scene s = buddhas({0.5});
  s.joints[0].body_b = "nobody";
  auto e = validate_scene(s);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "joints.0.body_b");

  s = buddhas({0.5});
  s.joints[0].kind = JointKind::wheel;
  s.joints[0].tuning.reset();
  EXPECT_EQ(validate_scene(s)->field, "joints.0.frequency_hz");

  s = buddhas({0.5});
  s.bodies[1].shape.kind = ShapeKind::polygon;
  s.bodies[1].shape.vertices = {{0, 0}, {1, 0}, {1, 1}, {0.9, 0.1}};  // not convex
  EXPECT_EQ(validate_scene(s)->field, "bodies.1.shape.vertices");

  s = buddhas({0.5});
  s.bodies[1].shape.kind = ShapeKind::polygon;
  s.bodies[1].shape.vertices = {{0, 0}, {1, 0}, {1, 1}, {0.001, 1.001}, {0, 1}};  // an edge Box2D would weld
  EXPECT_EQ(validate_scene(s)->field, "bodies.1.shape.vertices");

  s = buddhas({0.5});
  s.world.duration_s = 1e9;
  EXPECT_EQ(validate_scene(s)->field, "world.duration_s");
  s = buddhas(std::vector<double>(60, 0.0));  // 121 bodies and joints for 600 s at 60 fps x 5 substeps
  s.world.duration_s = 600;
  s.world.substeps = 5;
  EXPECT_EQ(validate_scene(s)->field, "world.duration_s");

  // A designer field out of range is refused by the core's validation with the joint's path.
  s = buddhas({0.5});
  s.joints[0].tuning->response_frames = 0.0;
  const SceneResult r = run_scene(s);
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "joints.0.response_frames");
}

TEST(Expectations, FailWhenTheFigureIsOutsideOrUndefined) {
  Scene s = buddhas({0.0, 0.95});
  s.expectations.push_back({"hanger0", Metric::frequency_error, std::nullopt, 0.03, std::nullopt, "", {}, {}});
  s.expectations.push_back({"hanger1", Metric::frequency_error, 0.5, std::nullopt, MassModel::box2d_reduced, "", {}, {}});
  s.expectations.push_back({"", Metric::finite, std::nullopt, std::nullopt, std::nullopt, "", {}, {}});
  CheckResult ok = check_scene(s);
  EXPECT_TRUE(ok.passed);
  EXPECT_EQ(ok.runs.size(), 2u);
  EXPECT_TRUE(ok.runs.front().stages.contains(Stage::expectations));

  s.expectations.push_back({"hanger1", Metric::frequency_error, std::nullopt, 0.03, MassModel::box2d_reduced, "", {}, {}});
  const CheckResult bad = check_scene(s);
  EXPECT_FALSE(bad.passed);
  EXPECT_FALSE(bad.results.back().passed);
}

}  // namespace
}  // namespace softtune::scene
