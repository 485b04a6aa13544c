#include "softtune/analytic.h"

#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/LU>

using namespace softtune;

namespace {
// Residual of x'' + 2 zeta omega x' + omega^2 x = 0 by central differences of the returned position.
double ode_residual(State s0, double omega, double zeta, double t) {
  const double d = 1e-4;
  const double xm = analytic_state(s0, omega, zeta, t - d).x, x0 = analytic_state(s0, omega, zeta, t).x,
               xp = analytic_state(s0, omega, zeta, t + d).x;
  const double acc = (xp - 2 * x0 + xm) / (d * d), vel = (xp - xm) / (2 * d);
  return acc + 2 * zeta * omega * vel + omega * omega * x0;
}
}  // namespace

TEST(Analytic, StartsAtTheInitialState) {
  for (double zeta : {0.0, 0.4, 1.0, 2.5}) {
    const State s = analytic_state({0.8, -1.5}, 7.0, zeta, 0.0);
    EXPECT_NEAR(s.x, 0.8, 1e-14);
    EXPECT_NEAR(s.v, -1.5, 1e-13);
  }
}

TEST(Analytic, SolvesTheOscillatorInEveryRegime) {
  for (double zeta : {0.0, 0.3, 1.0, 1.7, 20.0}) {
    for (double t : {0.05, 0.3, 1.1}) {
      const double omega = 6.0;
      EXPECT_NEAR(ode_residual({1.0, 0.5}, omega, zeta, t), 0.0, 2e-4 * omega * omega) << zeta << " " << t;
      // The velocity is the derivative of the position.
      const double d = 1e-6;
      const double fd = (analytic_state({1.0, 0.5}, omega, zeta, t + d).x - analytic_state({1.0, 0.5}, omega, zeta, t - d).x) / (2 * d);
      EXPECT_NEAR(analytic_state({1.0, 0.5}, omega, zeta, t).v, fd, 1e-6) << zeta << " " << t;
    }
  }
}

TEST(Analytic, UndampedIsACosine) {
  const double omega = 3.0;
  for (double t = 0; t < 5; t += 0.37) EXPECT_NEAR(analytic_state({2.0, 0.0}, omega, 0.0, t).x, 2.0 * std::cos(omega * t), 1e-13);
}

TEST(Analytic, RegimesJoinContinuouslyAtCriticalDamping) {
  const double omega = 4.0, t = 0.6;
  const double below = analytic_state({1.0, 0.0}, omega, 1.0 - 1e-7, t).x;
  const double at = analytic_state({1.0, 0.0}, omega, 1.0, t).x;
  const double above = analytic_state({1.0, 0.0}, omega, 1.0 + 1e-7, t).x;
  EXPECT_NEAR(below, at, 1e-6);
  EXPECT_NEAR(above, at, 1e-6);
}

TEST(Analytic, NoSpringIsFreeFlight) {
  const State s = analytic_state({1.0, 2.0}, 0.0, 0.0, 3.0);
  EXPECT_DOUBLE_EQ(s.x, 7.0);
  EXPECT_DOUBLE_EQ(s.v, 2.0);
}

TEST(Analytic, StepMatrixIteratesTheClosedForm) {
  // Iterating the one-step flow lands on the closed form at every step, in every regime.
  for (double zeta : {0.0, 0.5, 1.0, 2.5}) {
    const double omega = 2 * M_PI * 5.0, h = 1.0 / 60.0;
    const Eigen::Matrix2d e = analytic_step_matrix(omega, zeta, h);
    Eigen::Vector2d s(1.0, 0.0);
    for (int n = 1; n <= 36; ++n) {
      s = e * s;
      const State exact = analytic_state({1.0, 0.0}, omega, zeta, n * h);
      EXPECT_NEAR(s.x(), exact.x, 1e-12) << zeta << " " << n;
      EXPECT_NEAR(s.y(), exact.v, 1e-10) << zeta << " " << n;
    }
    // det E = exp(-2 zeta omega h): the flow shrinks areas as the damping takes energy out.
    EXPECT_NEAR(e.determinant(), std::exp(-2 * zeta * omega * h), 1e-12) << zeta;
  }
}

TEST(Analytic, ExactMotionCoversThreePeriods) {
  const double f = 0.5, omega = 2 * M_PI * f;
  const ExactMotion m = exact_motion(omega, 0.0, f, 1.0 / 60.0);
  EXPECT_DOUBLE_EQ(m.duration_s, 6.0);
  ASSERT_EQ(m.smooth_x.size(), static_cast<std::size_t>(kExactMotionPoints + 1));
  // Undamped from x0 = 1: a cosine, back at 1 after each whole period.
  for (std::size_t i = 0; i < m.smooth_x.size(); ++i) EXPECT_NEAR(m.smooth_x[i], std::cos(omega * i * m.smooth_dt_s), 1e-12);
  EXPECT_NEAR(m.smooth_x.back(), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(exact_motion(0.0, 0.0, 0.0, 0.01).duration_s, 1.0);  // no spring: one second
}
