// Tuning a scene in its engine (scene/engine_tuning.h) against engines whose answer is known:
// - a stand-in backend that is Box2D 2.4 with every spring it is given scaled (k x 0.6, c x 1.5) before Box2D sees
//   it, as an engine whose fields mean something else than Box2D's would: its solve is Box2D 2.4's own k, c
//   divided by those factors;
// - a stand-in engine that integrates one weight on one spring exactly (the continuous motion, RK4 at 1/400 of
//   the step): its solve is the continuous oscillator's k = m omega^2, c = 2 m zeta omega, not the implicit-Euler
//   k', c' that Box2D 2.4 needs for the same request in exact mode.
#include "softtune/scene/engine_tuning.h"

#include <gtest/gtest.h>

#include <numbers>

#include "app/preset_store.h"
#include "codec/scene_codec.h"
#include "softtune/scene/box2d_backend.h"
#include "scene_builders.h"
#include "../presets_dir.h"
#include "probe_result.h"

namespace softtune::scene {
namespace {

using test_support::kPresets;

constexpr double kEngineTuningKScale = 0.6, kEngineTuningCScale = 1.5;

std::unique_ptr<SceneWorld> engine_tuning_scaled_build(const SceneBuild& build, std::optional<FieldError>& error) {
  SceneBuild scaled = build;
  for (auto& s : scaled.springs) {
    if (s) *s = {s->stiffness * kEngineTuningKScale, s->damping * kEngineTuningCScale};
  }
  return kBox2DV24SceneBackend.build(scaled, error);
}

const SceneBackend kEngineTuningScaled{"box2d_scaled", "Box2D 2.4.1, springs scaled", kBox2DV24SceneBackend.settings,
                                       engine_tuning_scaled_build, kBox2DV24SceneBackend.fields,
                                       kBox2DV24SceneBackend.parse};

// The continuous engine: body 1 hangs from static body 0 on joint 0 (a distance spring) without gravity and
// without rotation; anything else is refused, naming the feature.
class EngineTuningContinuousWorld final : public SceneWorld {
 public:
  EngineTuningContinuousWorld(const Scene& s, const JointSpring& spring) : scene_(s), spring_(spring) {
    const JointSettings& j = s.joints[0];
    u_ = (j.anchor_b - j.anchor_a).normalized();
    length_ = (j.anchor_b - j.anchor_a).norm();
    rest_ = j.length.value_or(length_);
    start_ = s.bodies[1].position;
    start_length_ = length_;
    mass_ = *s.bodies[1].mass;
    velocity_ = s.bodies[1].linear_velocity.dot(u_);
  }
  void step_frame(int) override {
    const int n = 400 * scene_.world.substeps;
    const double dt = 1.0 / (scene_.world.fps * n);
    auto accel = [&](double x, double v) { return -(spring_.stiffness * x + spring_.damping * v) / mass_; };
    double x = length_ - rest_, v = velocity_;
    for (int i = 0; i < n; ++i) {  // RK4 on m x'' + c x' + k x = 0
      const double k1x = v, k1v = accel(x, v);
      const double k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
      const double k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
      const double k4x = v + dt * k3v, k4v = accel(x + dt * k3x, v + dt * k3v);
      x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
      v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    length_ = rest_ + x;
    velocity_ = v;
  }
  BodyState body(std::size_t i) const override {
    BodyState b;
    b.origin = b.centre = i == 0 ? scene_.bodies[0].position : start_ + (length_ - start_length_) * u_;
    if (i == 1) b.velocity = velocity_ * u_;
    return b;
  }
  std::vector<ContactSnapshot> contacts() const override { return {}; }

 private:
  const Scene& scene_;
  JointSpring spring_;
  Eigen::Vector2d u_, start_;
  double length_ = 0, rest_ = 0, start_length_ = 0, mass_ = 1, velocity_ = 0;
};

std::unique_ptr<SceneWorld> engine_tuning_continuous_build(const SceneBuild& build, std::optional<FieldError>& error) {
  const Scene& s = *build.scene;
  if (s.bodies.size() != 2 || !s.bodies[0].is_static || !s.bodies[1].fixed_rotation || !s.bodies[1].mass) {
    error = FieldError{"bodies", "continuous_test has one static and one non-rotating dynamic body with a mass"};
    return nullptr;
  }
  if (s.joints.size() != 1 || s.joints[0].kind != JointKind::distance || build.springs.empty() || !build.springs[0]) {
    error = FieldError{"joints.0.type", "continuous_test has one soft distance joint only"};
    return nullptr;
  }
  return std::make_unique<EngineTuningContinuousWorld>(s, *build.springs[0]);
}

const SceneBackend kEngineTuningContinuous{"continuous_test", "RK4, the continuous oscillator", {},
                                           engine_tuning_continuous_build, kBox2DV24SceneBackend.fields,
                                           kBox2DV24SceneBackend.parse};

Scene engine_tuning_preset(const std::string& name) { return codec::decode_scene(app::load_preset(kPresets, name)); }

RunOptions engine_tuning_in_scaled() {
  RunOptions o;
  o.backend = &kEngineTuningScaled;
  return o;
}

// One engine_tune_scene call and everything it fills.
struct EngineTuningSolve {
  Scene base;
  std::vector<std::optional<JointSpring>> springs;
  std::optional<ModalTuningResult> modal;
  EngineTuningResult out;
  StageList stages;
  std::optional<FieldError> error;
};

EngineTuningSolve engine_tuning_solve(const Scene& scene, const RunOptions& options) {
  EngineTuningSolve r;
  r.error = engine_tune_scene(scene, options, r.base, r.springs, r.modal, r.out, r.stages);
  return r;
}

TEST(EngineTuning, OnlyOtherEnginesWithoutGivenSpringsAreTunedInTheEngine) {
  const Scene vehicle = engine_tuning_preset("vehicle");
  EXPECT_FALSE(tunes_in_engine(vehicle, {}));
  RunOptions box2d;
  box2d.backend = &kBox2DV24SceneBackend;
  EXPECT_FALSE(tunes_in_engine(vehicle, box2d));
  RunOptions other = engine_tuning_in_scaled();
  EXPECT_TRUE(tunes_in_engine(vehicle, other));
  other.springs.resize(vehicle.joints.size());
  EXPECT_FALSE(tunes_in_engine(vehicle, other));  // a trial of the solve itself
  EXPECT_FALSE(tunes_in_engine(engine_tuning_preset("chain"), engine_tuning_in_scaled()));  // nothing tuned
}

// The vehicle's heave target (3 Hz, zeta 0.5, exact at 60 fps): the suspension's k, c solved in the scaled
// engine are Box2D 2.4's divided by the scales, and the heave in that engine meets the request.
TEST(EngineTuning, VehicleHeaveIsSolvedInTheEngine) {
  const Scene vehicle = engine_tuning_preset("vehicle");
  const EngineTuningSolve solve = engine_tuning_solve(vehicle, engine_tuning_in_scaled());
  ASSERT_FALSE(solve.error);
  const auto& [base, springs, modal, out, stages, error] = solve;
  ASSERT_TRUE(modal);
  EXPECT_TRUE(out.modal);
  EXPECT_EQ(out.engine, "box2d_scaled");
  EXPECT_FALSE(base.modal_tuning);
  EXPECT_DOUBLE_EQ(out.window_s, 2.0);  // the heave probe's to_s
  ASSERT_EQ(out.unknowns.size(), 1u);
  ASSERT_EQ(out.targets.size(), 1u);
  EXPECT_EQ(out.targets[0].probe, "heave");
  const EngineUnknown& u = out.unknowns[0];
  EXPECT_DOUBLE_EQ(u.start.stiffness, modal->groups[0].stiffness);
  EXPECT_TRUE(out.converged) << out.runs << " runs";
  EXPECT_LE(out.runs, kMaxEngineRuns);
  EXPECT_GT(out.iterations, 0);
  // The engine runs Box2D with k x 0.6, c x 1.5: Box2D's own solve is what it must end up with.
  EXPECT_NEAR(u.solved.stiffness * kEngineTuningKScale / u.start.stiffness, 1.0, 0.02);
  EXPECT_NEAR(u.solved.damping * kEngineTuningCScale / u.start.damping, 1.0, 0.03);
  ASSERT_EQ(springs.size(), vehicle.joints.size());
  for (const auto& s : springs) EXPECT_TRUE(s && s->stiffness == u.solved.stiffness);
  // Box2D 2.4 on its own solve measured what the tuning was started from.
  ASSERT_TRUE(out.targets[0].box2d_frequency_hz);
  EXPECT_NEAR(*out.targets[0].box2d_frequency_hz, 3.0, 0.09);
}

// run_scene in that engine: the answer's modal groups and the fields to type carry the engine's solve, and the
// confirming full run (6 s, the motor from 2 s) measures the heave within the solve's tolerance.
TEST(EngineTuning, TheAnswerCarriesTheEnginesSolve) {
  const SceneResult r = run_scene(engine_tuning_preset("vehicle"), engine_tuning_in_scaled());
  ASSERT_FALSE(r.error) << r.error->field << ": " << r.error->rule;
  ASSERT_TRUE(r.engine_tuning && r.modal_tuning);
  EXPECT_EQ(r.engine, "box2d_scaled");
  const JointSpring solved = r.engine_tuning->unknowns.at(0).solved;
  EXPECT_EQ(r.modal_tuning->groups.at(0).stiffness, solved.stiffness);
  EXPECT_EQ(r.modal_tuning->groups.at(0).damping, solved.damping);
  for (std::size_t j = 0; j < r.joint_fields.size(); ++j) {
    FieldError e;
    const auto typed = kEngineTuningScaled.parse(engine_tuning_preset("vehicle"), j, r.joint_fields[j], {}, e);
    ASSERT_TRUE(typed) << e.field;
    EXPECT_NEAR(typed->stiffness, solved.stiffness, 1e-6 * solved.stiffness);
    EXPECT_NEAR(typed->damping, solved.damping, 1e-6 * solved.damping);
  }
  const EngineTarget& heave = r.engine_tuning->targets.at(0);
  ASSERT_TRUE(heave.frequency_error && heave.damping_ratio_error);
  EXPECT_LT(std::abs(*heave.frequency_error), kEngineFrequencyTolerance);
  EXPECT_LT(std::abs(*heave.damping_ratio_error), kEngineDampingTolerance);
  ASSERT_TRUE(heave.start_frequency_hz);
  EXPECT_LT(*heave.start_frequency_hz, 2.8);  // Box2D's springs at 0.6 k are soft in this engine: sqrt(0.6) x 3 Hz
  EXPECT_TRUE(r.stages.contains(Stage::modal_solve));
  EXPECT_TRUE(r.stages.contains(Stage::engine_step));
}

// Per-joint requests: the four hangers of `buddhas` each carry one weight, so each joint's request is its own
// probe's response; each is solved on its own joint (the Jacobian's columns per joint).
TEST(EngineTuning, BuddhasHangersAreSolvedPerJoint) {
  const Scene buddhas = engine_tuning_preset("buddhas");
  const EngineTuningSolve solve = engine_tuning_solve(buddhas, engine_tuning_in_scaled());
  ASSERT_FALSE(solve.error);
  const auto& [base, springs, modal, out, stages, error] = solve;
  EXPECT_FALSE(modal);
  EXPECT_FALSE(out.modal);
  ASSERT_EQ(out.unknowns.size(), 4u);
  EXPECT_TRUE(out.converged) << out.runs << " runs";
  for (const EngineUnknown& u : out.unknowns) {
    EXPECT_NEAR(u.solved.stiffness * kEngineTuningKScale / u.start.stiffness, 1.0, 0.02) << u.id;
    EXPECT_NEAR(u.solved.damping * kEngineTuningCScale / u.start.damping, 1.0, 0.03) << u.id;
  }
  EXPECT_TRUE(out.coupled_probes.empty());
}

// The per-spring vehicle: Box2D 2.4's per-joint solve heaves at 1.29 Hz for 3 Hz asked, so the joints' travel
// is not their request in any engine: nothing is solved, the springs stay Box2D's, and the probes are listed.
TEST(EngineTuning, CoupledJointsKeepTheirSpringsAndAreListed) {
  const EngineTuningSolve solve = engine_tuning_solve(engine_tuning_preset("vehicle_per_spring"), engine_tuning_in_scaled());
  ASSERT_FALSE(solve.error) << solve.error->field << ": " << solve.error->rule;
  const auto& [base, springs, modal, out, stages, error] = solve;
  EXPECT_TRUE(out.unknowns.empty());
  EXPECT_EQ(out.runs, 0);
  EXPECT_TRUE(springs.empty());
  EXPECT_EQ(out.coupled_probes, (std::vector<std::string>{"rear_travel", "front_travel"}));
}

// 4 Hz, zeta 0.3 asked in exact mode at 60 fps: Box2D 2.4's per-joint solve is implicit Euler's k', c' (which
// the continuous engine runs too fast and too damped); the measured Newton lands on the continuous oscillator's
// k = m omega^2, c = 2 m zeta omega for the 1 kg weight -- an analytic answer, not the code's own.
TEST(EngineTuning, AContinuousEngineGetsTheContinuousSpring) {
  Scene s = test::hanging_weight(4.0, Oscillation::some);
  s.joints[0].tuning->oscillation.reset();
  s.joints[0].tuning->damping_ratio = 0.3;
  s.joints[0].tuning->mode = SoftMode::exact;
  s.oscillators.clear();
  s.probes = {test::probe("spring", ProbeKind::joint_length, "spring")};
  RunOptions o;
  o.backend = &kEngineTuningContinuous;
  const EngineTuningSolve solve = engine_tuning_solve(s, o);
  ASSERT_FALSE(solve.error);
  const EngineTuningResult& out = solve.out;
  ASSERT_EQ(out.unknowns.size(), 1u);
  EXPECT_TRUE(out.converged) << out.runs << " runs";
  const double omega = 2 * std::numbers::pi * 4.0, m = 1.0;
  const EngineUnknown& u = out.unknowns[0];
  EXPECT_GT(std::abs(u.start.stiffness / (m * omega * omega) - 1.0), 0.05);  // Box2D's k' is not the answer
  EXPECT_NEAR(u.solved.stiffness / (m * omega * omega), 1.0, 0.01);
  EXPECT_NEAR(u.solved.damping / (2 * m * 0.3 * omega), 1.0, 0.03);

  // run_scene tunes it the same way, and its confirming run meets the request.
  const SceneResult r = run_scene(s, o);
  ASSERT_FALSE(r.error) << r.error->field << ": " << r.error->rule;
  EXPECT_EQ(r.engine, "continuous_test");
  ASSERT_TRUE(r.engine_tuning);
  ASSERT_TRUE(r.engine_tuning->targets.at(0).frequency_error);
  EXPECT_LT(std::abs(*r.engine_tuning->targets[0].frequency_error), kEngineFrequencyTolerance);
  EXPECT_LT(std::abs(*r.engine_tuning->targets[0].damping_ratio_error), kEngineDampingTolerance);
  ASSERT_EQ(r.joint_fields.size(), 1u);
  FieldError e;
  const auto typed = kEngineTuningContinuous.parse(s, 0, r.joint_fields[0], {}, e);
  ASSERT_TRUE(typed);
  EXPECT_NEAR(typed->stiffness, u.solved.stiffness, 1e-6 * u.solved.stiffness);
}

// A scene the engine cannot build: the refusal comes back naming the feature and the engine.
TEST(EngineTuning, AnEngineRefusalIsTheAnswer) {
  RunOptions o;
  o.backend = &kEngineTuningContinuous;
  const SceneResult r = run_scene(engine_tuning_preset("vehicle"), o);
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "bodies");
  EXPECT_NE(r.error->rule.find("continuous_test"), std::string::npos);
}

}  // namespace
}  // namespace softtune::scene
