// Each engine's solver on the mass-ratio chain: with the link held fixed (a huge link mass) the weight's
// joint is one soft constraint, which must move exactly as the engine's one-constraint model of
// core/src/engines/ (or, for Box2D 2.4, softtune's soft step); and each limit the chain reports is
// confirmed by simulation just below and just above it.
#include "softtune/chain_solvers.h"

#include <gtest/gtest.h>

#include <numbers>

#include "softtune/engines/box2d_v3.h"
#include "softtune/engines/jolt.h"
#include "softtune/engines/rapier.h"
#include "softtune/methods.h"

namespace softtune {
namespace {

constexpr double kChainH = 1.0 / 60.0;
const double kChainOmega = 2.0 * std::numbers::pi * 10.0;
constexpr double kZeta = 0.1;

// The weight (1 kg) on a link of 1e12 kg: the weight's joint sees an effective mass of 1 kg to 1e-12.
ChainModel fixed_link(ChainSolver solver, int count, bool warm) {
  ChainModel m = chain_model(solver, count, warm, 1e-12, kChainOmega, kZeta, kChainH);
  m.link_mass = 1e12;
  return m;
}

// The weight's (x, v) over 30 steps from x2 = 1 against `reference`, which steps (x, v, lambda).
template <typename Reference>
void expect_weight_follows(const ChainModel& model, Reference reference) {
  ChainState s = ChainState::Zero();
  s[1] = 1.0;
  Eigen::Vector3d r(1.0, 0.0, 0.0);
  for (int i = 0; i < 30; ++i) {
    s = chain_step(s, model);
    r = reference(r);
    ASSERT_NEAR(s[1], r[0], 1e-9) << "step " << i;
    ASSERT_NEAR(s[3], r[1], 1e-8) << "step " << i;
  }
}

TEST(ChainSolvers, FixedLinkIsTheEnginesOneConstraintModel) {
  const double k = kChainOmega * kChainOmega, c = 2.0 * kZeta * kChainOmega;  // on 1 kg
  for (bool warm : {false, true}) {
    for (int count : {1, 4}) {
      // Box2D 2.4: the talk's soft step (softtune's Method::soft), whatever the iteration count.
      const StepModel soft = make_step_model(1.0, kChainOmega, kZeta, kChainH);
      expect_weight_follows(fixed_link(ChainSolver::box2d_v2_4, count, warm), [&](const Eigen::Vector3d& x) {
        const State n = step(Method::soft, {x[0], x[1]}, soft);
        return Eigen::Vector3d(n.x, n.v, 0.0);
      });
      // Box2D v3: box2d_v3_step_map carries (x, v, impulse).
      const Eigen::Matrix3d v3 = engines::box2d_v3_step_map(1.0, 10.0, kZeta, kChainH, count, warm);
      expect_weight_follows(fixed_link(ChainSolver::box2d_v3, count, warm),
                            [&](const Eigen::Vector3d& x) -> Eigen::Vector3d { return v3 * x; });
      // Jolt (one collision step, mNumVelocitySteps = count) and Rapier (count substeps).
      const Eigen::Matrix2d jolt = engines::jolt_step_map(1.0, k, c, kChainH, 1, 0.05);
      expect_weight_follows(fixed_link(ChainSolver::jolt, count, warm), [&](const Eigen::Vector3d& x) {
        const Eigen::Vector2d n = jolt * x.head<2>();
        return Eigen::Vector3d(n[0], n[1], 0.0);
      });
      const Eigen::Matrix2d rapier = engines::rapier_step_map(1.0, k, c, kChainH, count, 0.0);
      expect_weight_follows(fixed_link(ChainSolver::rapier, count, warm), [&](const Eigen::Vector3d& x) {
        const Eigen::Vector2d n = rapier * x.head<2>();
        return Eigen::Vector3d(n[0], n[1], 0.0);
      });
    }
  }
}

// Every solver at its default count, warm starting on, heavy weight (1e3): the bisected limit is stable
// when simulated 1 % below it and blows up 1 % above it (independent 2000-step runs, not the bracket's).
TEST(ChainSolvers, LimitsHoldUnderSimulationJustBelowAndAbove) {
  const std::vector<double> scan = default_chain_sweep_settings().frequency_ratios;
  for (ChainSolver solver : kAllChainSolvers) {
    const int count = chain_default_count(solver);
    const ChainLimit l = find_chain_limit(solver, count, true, 1e3, 0.0, kChainH, scan, 1000);
    if (l.kind != LimitKind::found) {
      EXPECT_EQ(l.kind, LimitKind::none_in_range) << chain_solver_name(solver);
      continue;
    }
    EXPECT_TRUE(l.confirmed) << chain_solver_name(solver);
    EXPECT_LE(*l.lowest_unstable_frequency_ratio / *l.highest_stable_frequency_ratio - 1.0, kLimitRelativeTolerance);
    auto at = [&](double fr) {
      return run_chain_case(chain_model(solver, count, true, 1e3, 2.0 * std::numbers::pi * fr / kChainH, 0.0, kChainH), 2000);
    };
    EXPECT_NE(at(0.99 * *l.highest_stable_frequency_ratio).observed, Verdict::unstable) << chain_solver_name(solver);
    EXPECT_EQ(at(1.01 * *l.lowest_unstable_frequency_ratio).observed, Verdict::unstable) << chain_solver_name(solver);
  }
}

// Box2D 2.4, one iteration, warm start, ratio 1e3: the grid's answer (0.159, its last stable point) sits a
// grid factor below the true limit; the next grid point (0.263) must be unstable and the limit between.
TEST(ChainSolvers, BisectionRefinesTheGridAnswer) {
  const std::vector<double> scan = default_chain_sweep_settings().frequency_ratios;
  const ChainLimit l = find_chain_limit(ChainSolver::box2d_v2_4, 1, true, 1e3, 0.0, kChainH, scan, 1000);
  ASSERT_EQ(l.kind, LimitKind::found);
  ASSERT_TRUE(l.scan_highest_stable_frequency_ratio);
  const auto next = std::upper_bound(scan.begin(), scan.end(), *l.scan_highest_stable_frequency_ratio);
  ASSERT_NE(next, scan.end());
  EXPECT_GT(*l.highest_stable_frequency_ratio, *l.scan_highest_stable_frequency_ratio);
  EXPECT_LT(*l.lowest_unstable_frequency_ratio, *next);
  EXPECT_EQ(run_chain_case(chain_model(ChainSolver::box2d_v2_4, 1, true, 1e3, 2.0 * std::numbers::pi * *next / kChainH, 0.0, kChainH), 1000).observed,
            Verdict::unstable);
}

TEST(ChainSolvers, NamesRoundTrip) {
  for (ChainSolver s : kAllChainSolvers) EXPECT_EQ(chain_solver_from_name(chain_solver_name(s)), s);
  EXPECT_FALSE(chain_solver_from_name("physx"));
}

}  // namespace
}  // namespace softtune
