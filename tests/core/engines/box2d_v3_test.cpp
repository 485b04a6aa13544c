// Box2D v3's model against the engine's own equations. Box2D v3 cannot be installed here, so the reference
// is a literal re-implementation, in this file, of the v3 solver loop for one body on one spring distance
// joint, written stage by stage from the source (erincatto/box2d HEAD: physics_world.c b2World_Step,
// solver.c b2SolverStep, joint.c b2PrepareJoint, distance_joint.c b2PrepareDistanceJoint /
// b2WarmStartDistanceJoint / b2SolveDistanceJoint, solver.h b2MakeSoft), in float as Box2D computes, in 2-D
// with the joint's own axis and length -- it shares no code with the model. And against the numbers issue 15
// measured in the real engine.
#include "softtune/engines/box2d_v3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "softtune/designer.h"
#include "softtune/exact_softness.h"
#include "softtune/response_fit.h"
#include "softtune/tune.h"
#include "engine_test_support.h"

namespace softtune::engines {
namespace {

// ---- The literal v3 loop (float) ----------------------------------------------------------------------

struct Vec2 {
  float x = 0.0f, y = 0.0f;
};
Vec2 add(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
Vec2 sub(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
Vec2 mul_sv(float s, Vec2 v) { return {s * v.x, s * v.y}; }
Vec2 mul_add(Vec2 a, float s, Vec2 b) { return {a.x + s * b.x, a.y + s * b.y}; }  // b2MulAdd
float dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
float length(Vec2 v) { return std::sqrt(v.x * v.x + v.y * v.y); }
Vec2 normalize(Vec2 v) {  // b2Normalize
  const float l = length(v);
  if (l < 1.1920929e-7f) return {0.0f, 0.0f};
  const float inv = 1.0f / l;
  return {inv * v.x, inv * v.y};
}

struct Soft {
  float biasRate, massScale, impulseScale;
};
Soft make_soft(float hertz, float zeta, float h) {  // solver.h b2MakeSoft
  if (hertz == 0.0f) return {0.0f, 0.0f, 0.0f};
  const float omega = 2.0f * 3.14159265359f * hertz;
  const float a1 = 2.0f * zeta + h * omega;
  const float a2 = h * omega * a1;
  const float a3 = 1.0f / (1.0f + a2);
  return {omega / a1, a2 * a3, a3};
}

struct LiteralWorld {
  // Ground: static body at the origin, anchor at its centre. Body B: dynamic point of mass m, rotation
  // locked (invI = 0), anchor at its centre, starting at (restLength + x0, 0).
  float invMassB;
  Vec2 centerB;
  Vec2 linearVelocityB;
  // b2DistanceJoint
  float length, hertz, dampingRatio;
  float lowerSpringForce = -3.4028235e38f, upperSpringForce = 3.4028235e38f;
  float impulse = 0.0f;
  Vec2 deltaCenter;
  float axialMass = 0.0f;
  Soft distanceSoftness{};
  bool enableWarmStarting = true;
};

void literal_step(LiteralWorld& w, float timeStep, int subStepCount) {
  // physics_world.c b2World_Step
  const int n = subStepCount < 1 ? 1 : subStepCount;
  const float h = timeStep / static_cast<float>(n);
  // body state for the step: deltaPosition starts at zero
  Vec2 deltaPosition{};
  Vec2 v = w.linearVelocityB;
  // b2PrepareJointsTask -> b2PrepareJoint -> b2PrepareDistanceJoint
  w.deltaCenter = sub(w.centerB, Vec2{});
  const Vec2 axis0 = normalize(w.deltaCenter);
  (void)axis0;
  const float k = 0.0f + w.invMassB;  // mA + mB + iA crA^2 + iB crB^2 (ground static, B rotation locked)
  w.axialMass = k > 0.0f ? 1.0f / k : 0.0f;
  w.distanceSoftness = make_soft(w.hertz, w.dampingRatio, h);
  if (!w.enableWarmStarting) w.impulse = 0.0f;
  for (int i = 0; i < n; ++i) {
    // b2IntegrateVelocitiesTask: no force, no gravity (world gravity set to zero), linearDamping 0
    const float linearDamping = 1.0f / (1.0f + h * 0.0f);
    v = mul_add(mul_sv(h * w.invMassB, Vec2{}), linearDamping, v);
    // b2WarmStartDistanceJoint
    {
      const Vec2 separation = add(w.deltaCenter, deltaPosition);
      const Vec2 axis = normalize(separation);
      const Vec2 P = mul_sv(w.impulse, axis);
      v = mul_add(v, w.invMassB, P);
    }
    // b2SolveDistanceJoint, solve (useBias = true) and, after integrating positions, relax (false); the
    // spring branch does not read useBias.
    auto solve = [&](bool useBias) {
      (void)useBias;
      const Vec2 separation = add(w.deltaCenter, deltaPosition);
      const float len = length(separation);
      const Vec2 axis = normalize(separation);
      if (w.hertz > 0.0f) {
        const float cdot = dot(axis, v);
        const float c = len - w.length;
        const float bias = w.distanceSoftness.biasRate * c;
        const float m = w.distanceSoftness.massScale * w.axialMass;
        const float oldImpulse = w.impulse;
        float imp = -m * (cdot + bias) - w.distanceSoftness.impulseScale * oldImpulse;
        w.impulse = std::clamp(w.impulse + imp, w.lowerSpringForce * h, w.upperSpringForce * h);
        imp = w.impulse - oldImpulse;
        const Vec2 P = mul_sv(imp, axis);
        v = mul_add(v, w.invMassB, P);
      }
    };
    solve(true);
    // b2IntegratePositionsTask
    deltaPosition = mul_add(deltaPosition, h, v);
    solve(false);
    // b2_stageRestitution and b2_stageStoreImpulses act on contacts only.
  }
  // b2FinalizeBodiesTask: the body's centre moves by its deltaPosition.
  w.centerB = add(w.centerB, deltaPosition);
  w.linearVelocityB = v;
}

std::vector<double> literal_run(double m, double hertz, double zeta, double dt, int substeps, bool warm,
                                double x0, int steps) {
  constexpr float kRest = 1.0f;
  LiteralWorld w{};
  w.invMassB = 1.0f / static_cast<float>(m);
  w.centerB = {kRest + static_cast<float>(x0), 0.0f};
  w.linearVelocityB = {0.0f, 0.0f};
  w.length = kRest;
  w.hertz = static_cast<float>(hertz);
  w.dampingRatio = static_cast<float>(zeta);
  w.enableWarmStarting = warm;
  std::vector<double> x{x0};
  for (int i = 0; i < steps; ++i) {
    literal_step(w, static_cast<float>(dt), substeps);
    x.push_back(static_cast<double>(w.centerB.x) - kRest);
  }
  return x;
}

// ---- helpers --------------------------------------------------------------------------------------------

SettingValues v3_settings(int substeps, bool warm = true) { return {static_cast<double>(substeps), warm ? 1.0 : 0.0}; }

using testing::target;

double hertz_of(const Parameters& p) { return *parameter_value(p, "b2DistanceJointDef::hertz"); }
double ratio_of(const Parameters& p) { return *parameter_value(p, "b2DistanceJointDef::dampingRatio"); }

std::vector<double> model_run(double hertz, double zeta, double dt, int substeps, bool warm, double x0, int steps) {
  const Eigen::Matrix3d a = box2d_v3_step_map(1.0, hertz, zeta, dt, substeps, warm);
  Eigen::Vector3d s(x0, 0.0, 0.0);
  std::vector<double> x{x0};
  for (int i = 0; i < steps; ++i) {
    s = a * s;
    x.push_back(s(0));
  }
  return x;
}

// ---- tests ----------------------------------------------------------------------------------------------

TEST(Box2DV3Model, StepMapIsTheLiteralSolverLoop) {
  // Sample by sample, the model's frame map follows the float re-implementation of the stages.
  for (int n : {1, 2, 4, 8}) {
    for (double zeta : {0.0, 0.3, 1.0, 2.0}) {
      for (double hz : {0.7, 4.0, 15.0}) {
        const double m = 2.5, dt = 1.0 / 60.0, x0 = 0.01;
        const std::vector<double> lit = literal_run(m, hz, zeta, dt, n, true, x0, 240);
        const std::vector<double> mod = model_run(hz, zeta, dt, n, true, x0, 240);
        double worst = 0.0;
        for (std::size_t i = 0; i < lit.size(); ++i) worst = std::max(worst, std::abs(lit[i] - mod[i]));
        // float: positions near 1 m carry ~6e-8 m; measured worst 8e-5 of x0 (0.7 Hz, 240 frames).
        EXPECT_LT(worst, 3e-4 * x0) << "n " << n << " zeta " << zeta << " hz " << hz;
      }
    }
  }
}

TEST(Box2DV3Model, WarmStartCancelsForOneSpring) {
  // The substep's impulse column is zero: massScale + impulseScale = 1 makes the solve stage undo the warm
  // start, so the carried impulse never reaches x or v and warm starting changes nothing.
  const Eigen::Matrix3d sub = box2d_v3_substep_map(3.0, 8.0, 0.2, 1.0 / 240.0);
  EXPECT_NEAR(sub(0, 2), 0.0, 1e-15);
  EXPECT_NEAR(sub(1, 2), 0.0, 1e-15);
  EXPECT_NEAR(sub(2, 2), 0.0, 1e-15);
  const Eigen::Matrix3d on = box2d_v3_step_map(3.0, 8.0, 0.2, 1.0 / 60.0, 4, true);
  const Eigen::Matrix3d off = box2d_v3_step_map(3.0, 8.0, 0.2, 1.0 / 60.0, 4, false);
  EXPECT_LT((on.topLeftCorner<2, 2>() - off.topLeftCorner<2, 2>()).norm(), 1e-14);
  const std::vector<double> a = literal_run(3.0, 8.0, 0.2, 1.0 / 60.0, 4, true, 0.01, 120);
  const std::vector<double> b = literal_run(3.0, 8.0, 0.2, 1.0 / 60.0, 4, false, 0.01, 120);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-6) << i;
}

TEST(Box2DV3Model, SubstepPolesInClosedForm) {
  // With is = 1 / (1 + 2 zeta W + W^2), W = h omega: det = is^2 (1 + 2 zeta W), tr = det (1 + is) / is.
  const double h = 1.0 / 240.0;
  for (double zeta : {0.0, 0.4, 1.3}) {
    const double w = h * 2.0 * std::numbers::pi * 10.0;
    const double is = 1.0 / (1.0 + 2.0 * zeta * w + w * w);
    const Eigen::Matrix3d a = box2d_v3_substep_map(1.0, 10.0, zeta, h);
    const Eigen::Matrix2d b = a.topLeftCorner<2, 2>();
    EXPECT_NEAR(b.determinant(), is * is * (1.0 + 2.0 * zeta * w), 1e-14);
    EXPECT_NEAR(b.trace(), is * (1.0 + 2.0 * zeta * w) * (1.0 + is), 1e-14);
  }
}

TEST(Box2DV3Model, IssueFifteenMeasurements) {
  // Issue 15, in the real v3 at 60 fps with one substep: asked 10 Hz undamped, standard mode gives
  // 10.0 Hz and zeta 0.71 (softtune's implicit Euler predicted 8.49 / 0.42); exact mode (k', c' for
  // implicit Euler, here at zeta 0.1) asked 10 Hz gives 17 Hz.
  const double m = 1.0, dt = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * 10.0;
  const EngineReport plain = kBox2DV3Model.report(target(10.0, 0.0, m, dt, spring_constants(m, omega, 0.0)), v3_settings(1));
  EXPECT_NEAR(hertz_of(plain.parameters), 10.0, 1e-12);
  EXPECT_EQ(ratio_of(plain.parameters), 0.0);
  ASSERT_TRUE(plain.predicted.frequency_hz);
  EXPECT_NEAR(*plain.predicted.frequency_hz, 10.0, 0.01);
  EXPECT_NEAR(*plain.predicted.damping_ratio, 0.707, 0.002);
  const ResponseFit fit = fit_response(literal_run(m, 10.0, 0.0, dt, 1, true, 0.01, 60), dt);
  EXPECT_NEAR(*fit.frequency_hz, *plain.predicted.frequency_hz, 0.01);
  EXPECT_NEAR(*fit.damping_ratio, *plain.predicted.damping_ratio, 0.002);

  const ExactSpring e = exact_spring(m, omega, 0.1, dt);
  const EngineReport exact_mode = kBox2DV3Model.report(target(10.0, 0.1, m, dt, e.spring), v3_settings(1));
  ASSERT_TRUE(exact_mode.predicted.frequency_hz);
  EXPECT_NEAR(*exact_mode.predicted.frequency_hz, 17.0, 0.05);
  const ResponseFit fit2 = fit_response(
      literal_run(m, hertz_of(exact_mode.parameters), ratio_of(exact_mode.parameters), dt, 1, true, 0.01, 60), dt);
  EXPECT_NEAR(*fit2.frequency_hz, *exact_mode.predicted.frequency_hz, 0.02);

  // Box2D's default four substeps, the same plain export: 10.03 Hz, zeta 0.253.
  const EngineReport four = kBox2DV3Model.report(target(10.0, 0.0, m, dt, spring_constants(m, omega, 0.0)),
                                                 default_settings(kBox2DV3Model));
  EXPECT_NEAR(*four.predicted.frequency_hz, 10.025, 0.002);
  EXPECT_NEAR(*four.predicted.damping_ratio, 0.2526, 0.0005);
}

TEST(Box2DV3Model, SpringHertzIsNotClamped) {
  // b2PrepareJoint clamps constraintHertz (the rigid rows) to 0.25 / h; the spring goes to b2MakeSoft as
  // typed. 100 Hz at 60 fps and 4 substeps (0.25 / h = 60 Hz): the literal loop follows the unclamped model.
  const double dt = 1.0 / 60.0;
  const std::vector<double> lit = literal_run(1.0, 100.0, 0.5, dt, 4, true, 0.01, 30);
  const std::vector<double> mod = model_run(100.0, 0.5, dt, 4, true, 0.01, 30);
  const std::vector<double> clamped = model_run(60.0, 0.5, dt, 4, true, 0.01, 30);
  double to_model = 0.0, to_clamped = 0.0;
  for (std::size_t i = 0; i < lit.size(); ++i) {
    to_model = std::max(to_model, std::abs(lit[i] - mod[i]));
    to_clamped = std::max(to_clamped, std::abs(lit[i] - clamped[i]));
  }
  EXPECT_LT(to_model, 1e-5);
  EXPECT_GT(to_clamped, 1e-4);
  // And the substep is stable at every hertz for dampingRatio >= 0.
  for (double hz : {1.0, 1e2, 1e4, 1e6}) {
    for (double zeta : {0.0, 0.5, 3.0}) {
      const Eigen::Matrix2d a = box2d_v3_step_map(1.0, hz, zeta, dt, 4, true).topLeftCorner<2, 2>();
      EXPECT_TRUE(predict_from_step_map(a, dt).stable) << hz << " " << zeta;
    }
  }
}

TEST(Box2DV3Model, ExactMeetsTheRequestInTheLiteralLoop) {
  int checked = 0;
  for (int n : {1, 4, 8}) {
    for (double hz : {0.5, 2.0, 6.0}) {
      for (double zeta : {0.2, 0.5, 1.0, 2.0}) {
        const double m = 0.7, dt = 1.0 / 60.0, omega = 2.0 * std::numbers::pi * hz;
        const EngineReport r = kBox2DV3Model.report(target(hz, zeta, m, dt, spring_constants(m, omega, zeta)), v3_settings(n));
        if (zeta < box2d_v3_min_damping_ratio(omega, dt / n) + 0.01) continue;
        ASSERT_TRUE(r.exact && r.exact_predicted) << n << " " << hz << " " << zeta;
        EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, hz * kExactFrequencyTolerance);
        EXPECT_NEAR(*r.exact_predicted->damping_ratio, zeta, kExactDampingTolerance);
        // The typed values, run through the literal loop, give the request.
        const int steps = static_cast<int>(3.0 / (hz * dt)) + 60;
        const ResponseFit fit = fit_response(literal_run(m, hertz_of(*r.exact), ratio_of(*r.exact), dt, n, true, 0.01, steps), dt);
        ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
        EXPECT_NEAR(*fit.frequency_hz, hz, 0.01 * hz) << n << " " << hz << " " << zeta;
        EXPECT_NEAR(*fit.damping_ratio, zeta, 0.02) << n << " " << hz << " " << zeta;
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 25);
}

TEST(Box2DV3Model, NearUndampedSlowSpringGetsTheNearestLegalValue) {
  // 1 Hz undamped at 60 fps and 4 substeps: the relax floor is about omega h / 2 = 0.013 (h = 1/240), within
  // 0.02: `exact` is the least-damped spring b2MakeSoft takes, flagged engine_inexact with its predicted
  // error, and the literal solver loop runs it at 1 Hz with that ratio.
  const double m = 0.7, dt = 1.0 / 60.0, hz = 1.0, omega = 2.0 * std::numbers::pi * hz;
  const double floor = box2d_v3_min_damping_ratio(omega, dt / 4);
  ASSERT_LT(floor, kNearestDampingTolerance);
  const EngineReport r = kBox2DV3Model.report(target(hz, 0.0, m, dt, spring_constants(m, omega, 0.0)), v3_settings(4));
  ASSERT_TRUE(r.exact && r.exact_predicted);
  EXPECT_EQ(r.warnings.back().code, WarningCode::engine_inexact);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, hz, hz * kExactFrequencyTolerance);
  EXPECT_NEAR(*r.exact_predicted->damping_ratio, floor, 1e-4);
  EXPECT_DOUBLE_EQ(r.warnings.back().limit, *r.exact_predicted->damping_ratio);
  EXPECT_GE(2.0 * ratio_of(*r.exact) + dt / 4 * 2.0 * std::numbers::pi * hertz_of(*r.exact), 0.0);
  const int steps = static_cast<int>(4.0 / (hz * dt));
  const ResponseFit fit = fit_response(literal_run(m, hertz_of(*r.exact), ratio_of(*r.exact), dt, 4, true, 0.01, steps), dt);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  EXPECT_NEAR(*fit.frequency_hz, hz, 1e-3 * hz);
  EXPECT_NEAR(*fit.damping_ratio, floor, 2e-3);
  // At 3 Hz the floor (0.039) is beyond 0.02: no exact.
  const double omega3 = 2.0 * std::numbers::pi * 3.0;
  EXPECT_FALSE(kBox2DV3Model.report(target(3.0, 0.0, m, dt, spring_constants(m, omega3, 0.0)), v3_settings(4)).exact);
}

TEST(Box2DV3Model, LowDampingIsBelowTheRelaxFloor) {
  // The floor is about omega h / 2; asked below it, exact is empty with an engine_inexact warning naming
  // the least damping ratio the substep shows at that frequency.
  const double h = 1.0 / 240.0, omega = 2.0 * std::numbers::pi * 10.0;
  const double floor = box2d_v3_min_damping_ratio(omega, h);
  EXPECT_NEAR(floor, omega * h / 2.0, 0.05 * omega * h);
  EXPECT_TRUE(box2d_v3_exact_spring(omega, floor + 0.01, h));
  EXPECT_FALSE(box2d_v3_exact_spring(omega, floor - 0.01, h));
  // On the boundary (2 dampingRatio + h omega_b -> 0) the model shows exactly the floor.
  const double phi = std::asin(std::sqrt(1.0 - std::exp(-2.0 * floor * omega * h)));
  const double hertz_b = std::sin(phi) / (2.0 * std::numbers::pi * h);
  const Eigen::Matrix2d a = box2d_v3_substep_map(1.0, hertz_b, -0.5 * h * 2.0 * std::numbers::pi * hertz_b * (1.0 - 1e-9), h)
                                .topLeftCorner<2, 2>();
  const Prediction p = predict_from_step_map(a, h);
  EXPECT_NEAR(*p.frequency_hz, 10.0, 1e-4);
  EXPECT_NEAR(*p.damping_ratio, floor, 1e-6);

  const double m = 1.0;
  const EngineReport r = kBox2DV3Model.report(target(10.0, 0.0, m, 1.0 / 60.0, spring_constants(m, omega, 0.0)),
                                              default_settings(kBox2DV3Model));
  EXPECT_FALSE(r.exact);
  bool warned = false;
  for (const Warning& w : r.warnings) {
    if (w.code == WarningCode::engine_inexact) {
      warned = true;
      EXPECT_EQ(w.engine, "box2d_v3");
      EXPECT_NEAR(w.limit, floor, 1e-9);
    }
  }
  EXPECT_TRUE(warned);
}

TEST(Box2DV3Model, RefusesWhatTheEngineDividesByZeroOn) {
  // softtune's exact spring at zeta = 0 has c' = -h k': dampingRatio = -h omega / 2 with h the whole step,
  // so 2 dampingRatio + (h / n) omega <= 0 for every subStepCount: b2MakeSoft divides by zero or flips.
  // Refused, and `predicted` is what the solver loop does with it: the literal loop runs it bounded or
  // growing as predicted, and where it oscillates at the predicted frequency and ratio.
  const double m = 1.0, dt = 1.0 / 60.0;
  int bounded = 0, growing = 0;
  for (double hz : {0.6, 2.0, 5.0}) {
    const double omega = 2.0 * std::numbers::pi * hz;
    for (int n : {2, 4, 8}) {
      const ExactSpring e = exact_spring(m, omega, 0.0, dt);
      const EngineReport r = kBox2DV3Model.report(target(hz, 0.0, m, dt, e.spring), v3_settings(n));
      ASSERT_FALSE(r.warnings.empty());
      EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses) << n;
      ASSERT_TRUE(r.predicted.frequency_hz && r.predicted.damping_ratio) << hz << " " << n;
      const std::vector<double> x = literal_run(m, hertz_of(r.parameters), ratio_of(r.parameters), dt, n, true, 0.01, 240);
      double largest = 0.0;
      for (double v : x) largest = std::max(largest, std::isfinite(v) ? std::abs(v) : INFINITY);
      if (r.predicted.stable) {
        ++bounded;
        EXPECT_LE(largest, 0.02) << hz << " " << n;
      } else {
        ++growing;
        // Seen to grow where the spectral radius says it does within the run (else the fit holds it).
        if (std::pow(r.predicted.spectral_radius, 240) >= 4.0) {
          EXPECT_GT(largest, 0.02) << hz << " " << n;
        }
      }
      // Fitted over the start (up to 4 x0) against the prediction.
      std::size_t end = 0;
      while (end < x.size() && std::isfinite(x[end]) && std::abs(x[end]) <= 0.04) ++end;
      if (end < 24) continue;
      const ResponseFit fit = fit_response(std::vector<double>(x.begin(), x.begin() + end), dt);
      ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio) << hz << " " << n;
      EXPECT_NEAR(*fit.frequency_hz / *r.predicted.frequency_hz, 1.0, 0.01) << hz << " " << n;
      EXPECT_NEAR(*fit.damping_ratio, *r.predicted.damping_ratio, 0.02) << hz << " " << n;
    }
  }
  std::printf("Box2D v3 refused exports in the literal loop: %d bounded, %d growing, as predicted\n", bounded, growing);
  EXPECT_GT(bounded + growing, 8);
  // No spring (k = 0): hertz 0 makes b2SolveDistanceJoint skip the spring.
  const EngineReport free = kBox2DV3Model.report(target(0.0, 0.0, m, dt, {0.0, 0.0}), default_settings(kBox2DV3Model));
  ASSERT_FALSE(free.warnings.empty());
  EXPECT_EQ(free.warnings[0].code, WarningCode::engine_refuses);
  // Every exact answer the model gives is inside the range.
  for (double zeta : {0.05, 0.2, 0.6, 1.0, 1.9}) {
    for (double hz : {0.3, 3.0, 12.0}) {
      const double w = 2.0 * std::numbers::pi * hz, h = dt / 4;
      if (const auto e = box2d_v3_exact_spring(w, zeta, h)) {
        EXPECT_GT(e->hertz, 0.0);
        EXPECT_GE(2.0 * e->damping_ratio + h * 2.0 * std::numbers::pi * e->hertz,
                  kBox2DV3FloatMargin * h * 2.0 * std::numbers::pi * e->hertz);
      }
    }
  }
}

TEST(Box2DV3Model, TuneCarriesTheReportWithTheRequestsSettings) {
  TuneRequest request;
  request.fps = 60.0;
  request.frequency_hz = 3.0;
  request.damping_ratio = 0.3;
  request.effective_mass = 2.0;
  const auto models = engine_models();
  std::size_t index = models.size();
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i]->name == "box2d_v3") index = i;
  }
  ASSERT_LT(index, models.size());
  request.engine_settings.resize(models.size());
  request.engine_settings[index] = v3_settings(8, false);
  const TuneResult result = tune(request);
  const EngineReport& r = result.engine_reports[index];
  EXPECT_EQ(*parameter_value(r.settings, "subStepCount"), 8.0);
  ASSERT_TRUE(r.exact && r.exact_predicted);
  EXPECT_NEAR(*r.exact_predicted->frequency_hz, 3.0, 3e-3);
  EXPECT_NEAR(hertz_of(r.parameters), 3.0, 1e-9);
}

}  // namespace
}  // namespace softtune::engines
