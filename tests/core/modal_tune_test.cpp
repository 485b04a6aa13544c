// The modal solve (modal_tune.h) against closed forms: a bar on two springs tuned for its heave (k = M w^2 / 2,
// c = zeta sqrt(2 k M)); in exact mode the talk's exact spring of the heave oscillator (exact_softness.h) at 30 and
// 60 fps; two groups placing heave and pitch of an off-centre bar whose springs decouple them; and the refusals.
#include "softtune/modal_tune.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "softtune/exact_softness.h"

namespace softtune::modes {
namespace {


// A bar (M, I) on vertical springs at x = -a and x = +b, its sideways motion held.
LinearModel bar(double mass, double inertia, double a, double b) {
  LinearModel m;
  m.gravity = {0, 0};
  m.bodies = {{"chassis", mass, inertia, {0, 1}}};
  for (double x : {-a, b}) {
    Row spring;
    spring.r_a = {x, 0};
    spring.r_b = {x, 0};
    spring.body_b = 0;
    spring.stiffness = 1000.0;
    spring.damping = 10.0;
    m.rows.push_back(spring);
  }
  Row hold;
  hold.body_b = 0;
  hold.axis = {1, 0};
  hold.rigid = true;
  m.rows.push_back(hold);
  return m;
}

TEST(ModalTune, OneGroupPlacesTheHeaveOnItsClosedForm) {
  const double mass = 120.0, f = 3.0, zeta = 0.5;
  const LinearModel m = bar(mass, 92.5, 1.1, 1.1);
  ReducedSystem s = reduce(m);
  ModalTuneRequest q;
  q.targets = {{0, Dof::y, f, zeta}};
  q.groups = {{{0, 1}, {1000.0, 10.0}}};
  const ModalTuneResult r = solve_modal_tune(m, s, q);
  ASSERT_FALSE(r.error) << r.error->rule;
  const double w = (2.0 * std::numbers::pi) * f, k = mass * w * w / 2.0;
  EXPECT_NEAR(r.groups[0].stiffness / k, 1.0, 1e-8);
  EXPECT_NEAR(r.groups[0].damping / (zeta * std::sqrt(2.0 * k * mass)), 1.0, 1e-8);
  EXPECT_LT(r.residual, 1e-9);
  EXPECT_EQ(r.modes[r.targets[0].mode].name, "chassis heave");
}

// The bar's heave solved for the discrete step h (both springs in one group, from a rough first guess).
ModalTuneResult exact_bar_heave(double mass, double f, double zeta, double h) {
  const LinearModel m = bar(mass, 92.5, 1.1, 1.1);
  ReducedSystem s = reduce(m);
  ModalTuneRequest q;
  q.targets = {{0, Dof::y, f, zeta}};
  q.groups = {{{0, 1}, {1000.0, 10.0}}};
  q.discrete = true;
  q.h = h;
  return solve_modal_tune(m, s, q);
}

TEST(ModalTune, ExactModeIsTheExactSpringOfTheHeaveAt30And60Fps) {
  const double mass = 120.0, f = 3.0, zeta = 0.5;
  for (double fps : {30.0, 60.0}) {
    const ModalTuneResult r = exact_bar_heave(mass, f, zeta, 1.0 / fps);
    ASSERT_FALSE(r.error) << r.error->rule;
    // Two springs carry the heave: each is half of the exact spring of (M, w, zeta) at h.
    const ExactSpring exact = exact_spring(mass, (2.0 * std::numbers::pi) * f, zeta, 1.0 / fps);
    EXPECT_NEAR(2.0 * r.groups[0].stiffness / exact.spring.stiffness, 1.0, 1e-7) << fps;
    EXPECT_NEAR(2.0 * r.groups[0].damping / exact.spring.damping, 1.0, 1e-7) << fps;
    const Pole& p = *r.modes[r.targets[0].mode].discrete;
    EXPECT_NEAR(p.frequency_hz, f, 1e-8);
    EXPECT_NEAR(p.damping_ratio, zeta, 1e-8);
  }
}

// A fast heave at a coarse step (8 Hz, zeta 0.5 at 30 fps: omega h = 1.68) needs the exact spring's c' < 0 --
// implicit Euler's own damping already exceeds the request -- which the exact solve reaches through its unknown
// ln(c + h k) (modal_tune.h): again each spring is half the exact spring of (M, w, zeta) at h.
TEST(ModalTune, ExactModeReachesANegativeDampingFastHeave) {
  const double mass = 120.0, f = 8.0, zeta = 0.5, h = 1.0 / 30.0;
  const ExactSpring exact = exact_spring(mass, (2.0 * std::numbers::pi) * f, zeta, h);
  ASSERT_LT(exact.spring.damping, 0.0);
  const ModalTuneResult r = exact_bar_heave(mass, f, zeta, h);
  ASSERT_FALSE(r.error) << r.error->rule;
  EXPECT_NEAR(2.0 * r.groups[0].stiffness / exact.spring.stiffness, 1.0, 1e-7);
  EXPECT_NEAR(2.0 * r.groups[0].damping / exact.spring.damping, 1.0, 1e-7);
  EXPECT_GT(r.groups[0].damping + h * r.groups[0].stiffness, 0.0);  // Box2D's gamma stays finite and positive
}

// Springs at -a and +b with k1 a = k2 b and c1 a = c2 b leave heave and pitch uncoupled:
// heave w^2 = (k1 + k2) / M, 2 zeta w = (c1 + c2) / M; pitch w^2 = (k1 a^2 + k2 b^2) / I, 2 zeta w = (c1 a^2 + c2 b^2) / I.
TEST(ModalTune, TwoGroupsPlaceHeaveAndPitchTogether) {
  const double mass = 100.0, inertia = 60.0, a = 0.8, b = 1.2;
  const double k1 = 6000.0, k2 = k1 * a / b, c1 = 300.0, c2 = c1 * a / b;
  const double wh = std::sqrt((k1 + k2) / mass), wp = std::sqrt((k1 * a * a + k2 * b * b) / inertia);
  const double zh = (c1 + c2) / mass / (2 * wh), zp = (c1 * a * a + c2 * b * b) / inertia / (2 * wp);
  const LinearModel m = bar(mass, inertia, a, b);
  ReducedSystem s = reduce(m);
  ModalTuneRequest q;
  q.targets = {{0, Dof::y, wh / (2.0 * std::numbers::pi), zh}, {0, Dof::angle, wp / (2.0 * std::numbers::pi), zp}};
  q.groups = {{{0}, {2000.0, 50.0}}, {{1}, {2000.0, 50.0}}};
  const ModalTuneResult r = solve_modal_tune(m, s, q);
  ASSERT_FALSE(r.error) << r.error->rule;
  EXPECT_NEAR(r.groups[0].stiffness / k1, 1.0, 1e-6);
  EXPECT_NEAR(r.groups[1].stiffness / k2, 1.0, 1e-6);
  EXPECT_NEAR(r.groups[0].damping / c1, 1.0, 1e-6);
  EXPECT_NEAR(r.groups[1].damping / c2, 1.0, 1e-6);
  EXPECT_FALSE(r.least_squares);
}

TEST(ModalTune, MoreTargetsThanUnknownsIsLeastSquaresWithItsResidual) {
  // One shared spring pair cannot give a symmetric bar both heave 1 Hz and pitch 3 Hz (their ratio is fixed).
  const LinearModel m = bar(120.0, 92.5, 1.1, 1.1);
  ReducedSystem s = reduce(m);
  ModalTuneRequest q;
  q.targets = {{0, Dof::y, 1.0, 0.3}, {0, Dof::angle, 3.0, 0.3}};
  q.groups = {{{0, 1}, {1000.0, 10.0}}};
  const ModalTuneResult r = solve_modal_tune(m, s, q);
  ASSERT_FALSE(r.error);
  EXPECT_TRUE(r.least_squares);
  EXPECT_GT(r.residual, 0.1);
  // The fixed ratio sqrt(d^2 M / I) of pitch to heave holds in the answer.
  const double ratio = r.modes[r.targets[1].mode].continuous->frequency_hz / r.modes[r.targets[0].mode].continuous->frequency_hz;
  EXPECT_NEAR(ratio, std::sqrt(1.1 * 1.1 * 120.0 / 92.5), 1e-6);
}

TEST(ModalTune, RefusesTargetsItCannotReachNamingThem) {
  const LinearModel m = bar(120.0, 92.5, 1.1, 1.1);
  ModalTuneRequest q;
  q.groups = {{{0, 1}, {1000.0, 10.0}}};
  q.discrete = true;
  q.h = 1.0 / 60.0;
  q.targets = {{0, Dof::y, 3.0, 0.5}, {0, Dof::y, 40.0, 0.1}};
  ReducedSystem s = reduce(m);
  ModalTuneResult r = solve_modal_tune(m, s, q);
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "targets.1.frequency_hz");

  // A second body on its own spring: the chassis springs do not move its heave.
  LinearModel two = bar(120.0, 92.5, 1.1, 1.1);
  two.bodies.push_back({"crate", 10.0, 1.0, {5, 1}});
  Row own;
  own.body_b = 1;
  own.stiffness = 800.0;
  own.damping = 5.0;
  two.rows.push_back(own);
  for (bool angular : {false, true}) {
    Row hold;
    hold.body_b = 1;
    hold.angular = angular;
    hold.axis = {1, 0};
    hold.rigid = true;
    two.rows.push_back(hold);
  }
  ReducedSystem s2 = reduce(two);
  ModalTuneRequest q2;
  q2.groups = {{{0, 1}, {1000.0, 10.0}}};
  q2.targets = {{0, Dof::y, 2.0, 0.5}, {1, Dof::y, 2.0, 0.5}};
  r = solve_modal_tune(two, s2, q2);
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "targets.1");
  EXPECT_NE(r.error->rule.find("crate heave"), std::string::npos) << r.error->rule;
}

}  // namespace
}  // namespace softtune::modes
