// Modes of closed-form systems (modes.h): two masses on two springs, a rigid bar on two springs (heave and
// pitch), a pendulum whose only stiffness is geometric (the rod's tension), and the discrete poles against
// implicit Euler on the equivalent 1-D oscillator.
#include "softtune/modes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "softtune/discrete_analysis.h"
#include "softtune/methods.h"

namespace softtune::modes {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

Row soft_vertical(int a, int b, Eigen::Vector2d r_a, Eigen::Vector2d r_b, double k, double c) {
  Row row;
  row.body_a = a;
  row.body_b = b;
  row.r_a = r_a;
  row.r_b = r_b;
  row.axis = {0, 1};
  row.stiffness = k;
  row.damping = c;
  return row;
}

Row rigid(int body, bool angular, Eigen::Vector2d axis = {1, 0}) {
  Row row;
  row.body_b = body;
  row.angular = angular;
  row.axis = axis;
  row.rigid = true;
  return row;
}

// wall -k1- m1 -k2- m2, vertical, no gravity: omega^2 are the eigenvalues of M^-1 [[k1 + k2, -k2], [-k2, k2]].
TEST(Modes, TwoMassesOnTwoSpringsMatchTheCharacteristicEquation) {
  const double m1 = 2.0, m2 = 1.0, k1 = 300.0, k2 = 100.0;
  LinearModel m;
  m.gravity = {0, 0};
  m.bodies = {{"lower", m1, 1.0, {0, 1}}, {"upper", m2, 1.0, {0, 2}}};
  m.rows = {soft_vertical(-1, 0, {0, 0}, {0, 0}, k1, 0), soft_vertical(0, 1, {0, 0}, {0, 0}, k2, 0),
            rigid(0, false), rigid(0, true), rigid(1, false), rigid(1, true)};
  const ReducedSystem s = reduce(m);
  ASSERT_EQ(s.null_space.cols(), 2);
  const auto modes = modes_of(m, s, 0.0);
  ASSERT_EQ(modes.size(), 2u);
  // det(K - w2 M) = 0: m1 m2 w^4 - (m1 k2 + m2 (k1 + k2)) w^2 + k1 k2 = 0.
  const double b = m1 * k2 + m2 * (k1 + k2), disc = std::sqrt(b * b - 4 * m1 * m2 * k1 * k2);
  const double w_slow = std::sqrt((b - disc) / (2 * m1 * m2)), w_fast = std::sqrt((b + disc) / (2 * m1 * m2));
  EXPECT_NEAR(modes[0].undamped_frequency_hz, w_slow / kTwoPi, 1e-8);
  EXPECT_NEAR(modes[1].undamped_frequency_hz, w_fast / kTwoPi, 1e-8);
  ASSERT_TRUE(modes[0].continuous);
  EXPECT_NEAR(modes[0].continuous->frequency_hz, w_slow / kTwoPi, 1e-8);
  EXPECT_NEAR(modes[0].continuous->damping_ratio, 0.0, 1e-9);
  // Slow mode: both move the same way, amplitude ratio x2/x1 = k2 / (k2 - m2 w^2).
  const double ratio = k2 / (k2 - m2 * w_slow * w_slow);
  EXPECT_NEAR(modes[0].shape[4] / modes[0].shape[1], ratio, 1e-7);
  EXPECT_EQ(modes[0].name, "upper heave");
}

// A bar (M, I) on two equal vertical springs at +-d, x held: heave w^2 = 2k/M, pitch w^2 = 2 k d^2 / I,
// damping ratios c / sqrt(2 k M) and c d^2 / sqrt(2 k d^2 I) (each an oscillator (M, 2k, 2c) / (I, 2kd^2, 2cd^2)).
TEST(Modes, RigidBarOnTwoSpringsHeavesAndPitchesAsItsFormulas) {
  const double mass = 120.0, inertia = 92.5, d = 1.1, k = 4000.0, c = 200.0;
  LinearModel m;
  m.gravity = {0, 0};
  m.bodies = {{"chassis", mass, inertia, {0, 1}}};
  m.rows = {soft_vertical(-1, 0, {-d, 0}, {-d, 0}, k, c), soft_vertical(-1, 0, {d, 0}, {d, 0}, k, c), rigid(0, false)};
  const ReducedSystem s = reduce(m);
  const auto modes = modes_of(m, s, 1.0 / 60.0);
  ASSERT_EQ(modes.size(), 2u);
  const double w_heave = std::sqrt(2 * k / mass), w_pitch = std::sqrt(2 * k * d * d / inertia);
  const Mode& heave = modes[0].name == "chassis heave" ? modes[0] : modes[1];
  const Mode& pitch = modes[0].name == "chassis pitch" ? modes[0] : modes[1];
  ASSERT_EQ(heave.name, "chassis heave");
  ASSERT_EQ(pitch.name, "chassis pitch");
  EXPECT_NEAR(heave.undamped_frequency_hz, w_heave / kTwoPi, 1e-8);
  EXPECT_NEAR(pitch.undamped_frequency_hz, w_pitch / kTwoPi, 1e-8);
  ASSERT_TRUE(heave.continuous && pitch.continuous);
  EXPECT_NEAR(heave.continuous->damping_ratio, c / std::sqrt(2 * k * mass), 1e-8);
  EXPECT_NEAR(pitch.continuous->damping_ratio, c * d * d / std::sqrt(2 * k * d * d * inertia), 1e-8);
  EXPECT_NEAR(heave.continuous->frequency_hz, w_heave / kTwoPi, 1e-8);
  EXPECT_EQ(find_mode(modes, 0, Dof::y), &heave - modes.data());
  EXPECT_EQ(find_mode(modes, 0, Dof::angle), &pitch - modes.data());

  // At the step: implicit Euler on the 1-D oscillator (M, 2k, 2c) has the same poles as the bar's heave.
  const double h = 1.0 / 60.0;
  const StepModel one_d = make_step_model(mass, w_heave, c / std::sqrt(2 * k * mass), h);
  const DiscreteAnalysis expected = analyze(Method::implicit_euler, one_d, w_heave, c / std::sqrt(2 * k * mass));
  ASSERT_TRUE(heave.discrete);
  EXPECT_NEAR(heave.discrete->frequency_hz, *expected.achieved_frequency_hz, 1e-8);
  EXPECT_NEAR(heave.discrete->damping_ratio, *expected.achieved_damping_ratio, 1e-8);
  EXPECT_LT(heave.discrete->frequency_hz, heave.continuous->frequency_hz);  // implicit Euler runs slow
}

// track_mode follows a mode by its shape: the bar's heave and pitch are found from their own shapes, and when
// the springs move out until pitch is faster than heave (the order of `modes` swaps), each shape still finds its
// own mode (their overlap is 0: heave and pitch of a symmetric bar are M-orthogonal).
TEST(Modes, TrackModeFollowsAShapeAcrossAFrequencyCrossing) {
  // Springs at +-0.5 m: pitch w^2 = 2 k d^2 / I = 21.6 below heave w^2 = 2 k / M = 66.7.
  const double mass = 120.0, inertia = 92.5, d = 0.5;
  LinearModel m;
  m.gravity = {0, 0};
  m.bodies = {{"chassis", mass, inertia, {0, 1}}};
  m.rows = {soft_vertical(-1, 0, {-d, 0}, {-d, 0}, 4000.0, 200.0), soft_vertical(-1, 0, {d, 0}, {d, 0}, 4000.0, 200.0), rigid(0, false)};
  ReducedSystem s = reduce(m);
  const auto before = modes_of(m, s, 0.0);
  const int heave = find_mode(before, 0, Dof::y), pitch = find_mode(before, 0, Dof::angle);
  EXPECT_EQ(track_mode(m, before, before[heave].shape), heave);
  EXPECT_EQ(track_mode(m, before, before[pitch].shape), pitch);
  // The springs moved out to +-3 m: pitch w^2 = 778 is now above heave's 66.7.
  m.rows = {soft_vertical(-1, 0, {-3, 0}, {-3, 0}, 4000.0, 200.0), soft_vertical(-1, 0, {3, 0}, {3, 0}, 4000.0, 200.0), rigid(0, false)};
  s = reduce(m);
  const auto after = modes_of(m, s, 0.0);
  ASSERT_EQ(before[0].name, "chassis pitch");
  ASSERT_EQ(after[0].name, "chassis heave");
  EXPECT_EQ(after[track_mode(m, after, before[heave].shape)].name, "chassis heave");
  EXPECT_EQ(after[track_mode(m, after, before[pitch].shape)].name, "chassis pitch");
}

// A pendulum has no spring at all: its stiffness is the rod's tension times the rod's curvature (-f H), and
// rigid_row_forces finds that tension. A bob held at its centre by a rod of length L swings at w^2 = g / L
// (its spin about the centre is free); a spring of stiffness k in place of the rod adds the bounce w^2 = k / m.
TEST(Modes, PendulumStiffnessIsGeometric) {
  const double mass = 3.0, inertia = 0.02, length = 1.5, g = 9.81;
  LinearModel m;
  m.gravity = {0, -g};
  m.bodies = {{"bob", mass, inertia, {0, -length}}};
  Row rod;
  rod.body_b = 0;
  rod.frame = AxisFrame::along_anchors;
  rod.rigid = true;  // r_a = (0, 0) is the pivot (a world point), r_b = 0 the bob's centre
  m.rows = {rod};
  EXPECT_LT(rigid_row_forces(m), 1e-8);
  EXPECT_NEAR(m.rows[0].force, -mass * g, 1e-7);  // pulls towards the pivot: against +C, the rod's length
  const auto modes = modes_of(m, reduce(m), 0.0);
  ASSERT_EQ(modes.size(), 2u);
  EXPECT_TRUE(modes[0].free);  // the spin
  EXPECT_NEAR(modes[1].undamped_frequency_hz * kTwoPi, std::sqrt(g / length), 1e-6);
  EXPECT_EQ(modes[1].name, "bob surge");

  // The same bob on a spring preloaded by its weight: the swing keeps g / L, the bounce is k / m.
  const double k = 500.0;
  m.rows[0].rigid = false;
  m.rows[0].stiffness = k;
  m.rows[0].force = -mass * g;
  const auto sprung = modes_of(m, reduce(m), 0.0);
  ASSERT_EQ(sprung.size(), 3u);
  EXPECT_NEAR(sprung[1].undamped_frequency_hz * kTwoPi, std::sqrt(g / length), 1e-6);
  EXPECT_NEAR(sprung[2].undamped_frequency_hz * kTwoPi, std::sqrt(k / mass), 1e-6);
  EXPECT_EQ(sprung[2].name, "bob heave");
}

}  // namespace
}  // namespace softtune::modes
