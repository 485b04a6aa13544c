#pragma once
// What the engine model tests share: the target a tune hands a model, and the check that a step map is
// implicit Euler (the talk's soft step), which several engines' steps reduce to.

#include <gtest/gtest.h>

#include <numbers>

#include "softtune/engines/engine_model.h"
#include "softtune/integrators.h"

namespace softtune::engines::testing {

inline constexpr double kPi = std::numbers::pi;

/// The target of a request for `hz` Hz, damping ratio `zeta`, effective mass `m` (kg), step `h` (s), with
/// softtune's spring `spring` (k, c of the mode).
inline Target target(double hz, double zeta, double m, double h, SpringConstants spring) {
  Target t;
  t.effective_mass = m;
  t.omega = 2.0 * std::numbers::pi * hz;
  t.damping_ratio = zeta;
  t.dt = h;
  t.spring = spring;
  return t;
}

/// `a` maps (x, v) as implicit Euler on (m, k, c) over h does (core/integrators.h), on three states.
inline void expect_implicit_euler(const Eigen::Matrix2d& a, double m, double k, double c, double h) {
  for (State s0 : {State{1.0, 0.0}, State{0.0, 1.0}, State{0.3, -2.0}}) {
    const State s1 = implicit_euler_step(s0, Oscillator{m, k, c}, h);
    EXPECT_NEAR(a(0, 0) * s0.x + a(0, 1) * s0.v, s1.x, 1e-12);
    EXPECT_NEAR(a(1, 0) * s0.x + a(1, 1) * s0.v, s1.v, 1e-12);
  }
}

/// A refused export the engine holds still (a rigid joint, an inactive row): refused first, no frequency,
/// and the marginal poles 1 of a stretch that stays where it was released.
inline void expect_refused_and_held(const EngineReport& r) {
  EXPECT_FALSE(r.predicted.frequency_hz);
  EXPECT_TRUE(r.predicted.stable);
  EXPECT_EQ(r.predicted.spectral_radius, 1.0);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings[0].code, WarningCode::engine_refuses);
}

}  // namespace softtune::engines::testing
