// The sequential-impulse chain: converged Gauss-Seidel equals the direct implicit solve, its stability
// prediction equals the simulation, and warm starting limits the stable frequency at high mass ratios.
#include "softtune/sequential_impulse.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <numbers>

namespace softtune {
namespace {

// The direct solve the iterations converge to: (J M^-1 J^T + Gamma / h) lambda = -(J v + (B / h) C),
// v' = v + M^-1 J^T lambda, x' = x + h v', written here from the constraint definitions.
ChainState direct_step(const ChainState& s, const ChainModel& m) {
  const double m1 = m.link_mass, m2 = m.link_mass * m.mass_ratio;
  Eigen::Matrix2d jac;
  jac << 1, 0, -1, 1;
  const Eigen::Matrix2d inv_mass = Eigen::Vector2d(1 / m1, 1 / m2).asDiagonal();
  const Eigen::Matrix2d k = jac * inv_mass * jac.transpose();
  Eigen::Matrix2d gamma = Eigen::Matrix2d::Zero(), bias = Eigen::Matrix2d::Zero();
  for (int j = 0; j < 2; ++j) {
    const double m_eff = 1.0 / k(j, j);
    const Softness soft = softness_from_spring(m_eff * m.omega * m.omega, 2 * m_eff * m.damping_ratio * m.omega, m.h);
    gamma(j, j) = soft.gamma / m.h;
    bias(j, j) = soft.beta / m.h;
  }
  const Eigen::Vector2d x = s.head<2>(), v = s.segment<2>(2);
  const Eigen::Vector2d lambda = (k + gamma).ldlt().solve(-(jac * v + bias * (jac * x)));
  const Eigen::Vector2d v1 = v + inv_mass * jac.transpose() * lambda;
  ChainState out;
  out << x + m.h * v1, v1, lambda;
  return out;
}

TEST(SequentialImpulse, ConvergedIterationsEqualTheDirectSolve) {
  const ChainModel model{1.0, 10.0, 400, 2 * std::numbers::pi * 5.0, 0.3, 1.0 / 60.0, false};
  for (int i = 0; i < 4; ++i) {
    const ChainState unit = ChainState::Unit(i);
    const ChainState gs = chain_step(unit, model), direct = direct_step(unit, model);
    EXPECT_LT((gs.head<4>() - direct.head<4>()).norm(), 1e-9) << i;
  }
}

// Every default chain case: the 6x6 step matrix's verdict equals the simulated one.
TEST(SequentialImpulse, StepMatrixPredictsTheSimulation) {
  ChainSweepSettings s = default_chain_sweep_settings();
  s.solvers = {ChainSolver::box2d_v2_4};
  const ChainSweepResult r = run_chain_sweep(s);
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_EQ(r.cases.size(), 7u * 5u * 16u * 2u);
}

TEST(SequentialImpulse, WarmStartingLimitsTheStableFrequencyAtHighMassRatio) {
  ChainSweepSettings s = default_chain_sweep_settings();
  s.solvers = {ChainSolver::box2d_v2_4};
  s.mass_ratios = {1e3};
  s.iterations = {1};
  const ChainSweepResult r = run_chain_sweep(s);
  ASSERT_EQ(r.limits.size(), 2u);
  const ChainLimit& cold = r.limits[0];
  const ChainLimit& warm = r.limits[1];
  EXPECT_FALSE(cold.warm_start);
  EXPECT_TRUE(cold.stable_over_whole_scan);
  EXPECT_TRUE(warm.warm_start);
  EXPECT_FALSE(warm.stable_over_whole_scan);
  ASSERT_TRUE(warm.highest_stable_frequency_ratio);
  EXPECT_LT(*warm.highest_stable_frequency_ratio, 0.5);
  EXPECT_EQ(r.mismatches, 0u);
}

TEST(SequentialImpulse, WithoutWarmStartingTheImpulseColumnsAreZero) {
  const ChainMatrix a = chain_step_matrix({1.0, 100.0, 4, 2 * std::numbers::pi * 10.0, 0.0, 1.0 / 60.0, false});
  EXPECT_EQ(a.col(4).norm(), 0.0);
  EXPECT_EQ(a.col(5).norm(), 0.0);
}

}  // namespace
}  // namespace softtune
