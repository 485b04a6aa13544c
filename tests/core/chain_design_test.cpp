// The chain's design answer, checked by simulation rather than by the code's own bisection: the fewest
// count it names keeps the chain stable up to margin x the asked frequency, and one count fewer blows up
// at or below it; the limit with the user's settings is stable just below and unstable just above.
#include "softtune/chain_design.h"

#include <gtest/gtest.h>

#include <numbers>

#include "softtune/chain_solvers.h"

namespace softtune {
namespace {

constexpr double kDesignH = 1.0 / 60.0;

Verdict simulated(const ChainSolverSettings& s, int count, double ratio, double frequency_hz) {
  const ChainModel m = chain_model_for(s, count, ratio, 2.0 * std::numbers::pi * frequency_hz, 0.0);
  return run_chain_case(m, 2000).observed;
}

// A heavy weight (1e3) at 60 fps: Box2D 2.4 with one velocity iteration blows up above about 13.5 Hz and
// Jolt's above about 17 Hz, so 20 Hz needs more iterations; Box2D v3 with one substep above about 25 Hz,
// so 30 Hz needs more substeps.
TEST(ChainDesign, FewestCountHoldsWithMarginAndOneFewerDoesNot) {
  const std::pair<ChainSolver, double> cases[] = {
      {ChainSolver::box2d_v2_4, 20.0}, {ChainSolver::jolt, 20.0}, {ChainSolver::box2d_v3, 30.0}};
  for (const auto& [solver, frequency] : cases) {
    ChainDesignRequest q;
    q.mass_ratio = 1e3;
    q.frequency_hz = frequency;
    q.margin = 1.25;
    q.solvers.push_back({solver, 1, true, kDesignH, std::nullopt, 1});
    const std::vector<ChainDesign> answer = design_chain(q);
    ASSERT_EQ(answer.size(), 1u);
    for (const ChainDesign& d : answer) {
      const char* name = chain_solver_name(d.settings.solver).data();
      EXPECT_FALSE(d.stable_at_target) << name;  // one iteration or substep is not enough there
      ASSERT_TRUE(d.fewest_count) << name;
      const int n = *d.fewest_count;
      EXPECT_GT(n, 1) << name;
      // Stable (by simulation) at the asked frequency and at margin x it with n; unstable at margin x with n - 1
      // or below it.
      EXPECT_NE(simulated(d.settings, n, q.mass_ratio, q.frequency_hz), Verdict::unstable) << name;
      EXPECT_NE(simulated(d.settings, n, q.mass_ratio, q.margin * q.frequency_hz), Verdict::unstable) << name;
      ASSERT_TRUE(d.fewest_count_limit_hz);
      EXPECT_GE(*d.fewest_count_limit_hz, q.margin * q.frequency_hz) << name;
      bool fewer_blows_up = false;
      for (double f = q.frequency_hz * 0.5; f <= q.margin * q.frequency_hz * 1.0001; f *= 1.02) {
        fewer_blows_up = fewer_blows_up || simulated(d.settings, n - 1, q.mass_ratio, f) == Verdict::unstable;
      }
      EXPECT_TRUE(fewer_blows_up) << name;
    }
  }
}

// With the user's settings: the reported highest stable frequency is stable 1 % below, unstable 1 % above
// (independent 2000-step simulations), and stable_at_target agrees with a simulation at the target.
TEST(ChainDesign, LimitWithTheUsersSettingsHoldsUnderSimulation) {
  ChainDesignRequest q;
  q.mass_ratio = 100.0;
  q.frequency_hz = 12.0;
  q.solvers = {{ChainSolver::box2d_v2_4, 2, true, kDesignH, std::nullopt, 1}, {ChainSolver::jolt, 4, true, kDesignH, 0.0, 1}};
  for (const ChainDesign& d : design_chain(q)) {
    ASSERT_EQ(d.limit.kind, LimitKind::found);
    EXPECT_TRUE(d.limit.confirmed);
    const double f = *d.limit.highest_stable_frequency_hz;
    EXPECT_NE(simulated(d.settings, d.settings.count, q.mass_ratio, 0.99 * f), Verdict::unstable);
    EXPECT_EQ(simulated(d.settings, d.settings.count, q.mass_ratio, 1.01 * f), Verdict::unstable);
    EXPECT_EQ(d.stable_at_target, simulated(d.settings, d.settings.count, q.mass_ratio, q.frequency_hz) != Verdict::unstable);
  }
}

// Jolt's linear damping, when the user sets it to 0, is Box2D 2.4's sequential impulses exactly.
TEST(ChainDesign, JoltWithoutDampingIsBox2D24) {
  const ChainSolverSettings jolt{ChainSolver::jolt, 3, true, kDesignH, 0.0};
  const ChainModel a = chain_model_for(jolt, 3, 1e3, 40.0, 0.1);
  const ChainModel b = chain_model(ChainSolver::box2d_v2_4, 3, true, 1e3, 40.0, 0.1, kDesignH);
  EXPECT_EQ((chain_step_matrix(a) - chain_step_matrix(b)).norm(), 0.0);
}

}  // namespace
}  // namespace softtune
