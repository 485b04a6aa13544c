// The chain question in the request's own terms (core/src/tune_chain.cpp): each solver's count and warm
// start come from the engine settings the user typed (or the engine's documented defaults), the step is
// the request's engine step 1 / (fps substeps), and each joint is tuned to the frequency the request ends
// with after any clamp.
#include "softtune/tune_chain.h"

#include <gtest/gtest.h>

#include <string_view>

#include "softtune/chain_solvers.h"
#include "softtune/engines/engine_model.h"

namespace softtune {
namespace {

TuneRequest chain_tune_request() {
  TuneRequest q;
  q.fps = 60.0;
  q.substeps = 2;
  q.frequency_hz = 5.0;
  q.damping_ratio = 0.5;
  q.effective_mass = 1.0;
  q.chain = ChainAsk{};
  q.chain->mass_ratio = 10.0;
  return q;
}

// Sets one engine setting by its engine's own name, the others at that engine's defaults.
void set_engine_setting(TuneRequest& q, std::string_view engine, std::string_view setting, double value) {
  const auto models = engines::engine_models();
  q.engine_settings.resize(models.size());
  for (std::size_t i = 0; i < models.size(); ++i) {
    if (models[i]->name != engine) continue;
    if (q.engine_settings[i].empty()) q.engine_settings[i] = engines::default_settings(*models[i]);
    for (std::size_t j = 0; j < models[i]->settings.size(); ++j) {
      if (models[i]->settings[j].name == setting) {
        q.engine_settings[i][j] = value;
        return;
      }
    }
  }
  FAIL() << engine << " has no setting " << setting;
}

const ChainSolverSettings& solver_of(const ChainDesignRequest& d, ChainSolver solver) {
  for (const ChainSolverSettings& s : d.solvers) {
    if (s.solver == solver) return s;
  }
  ADD_FAILURE() << "no " << chain_solver_name(solver) << " in the design request";
  return d.solvers.front();
}

ChainDesignRequest design_of(const TuneRequest& q) { return chain_design_request(q, tune(q)); }

TEST(TuneChain, WithoutSettingsEachSolverRunsItsEnginesDefaultsAtTheRequestsStep) {
  const TuneRequest q = chain_tune_request();
  const ChainDesignRequest d = design_of(q);
  EXPECT_EQ(d.mass_ratio, 10.0);
  EXPECT_EQ(d.margin, kDefaultChainMargin);
  EXPECT_DOUBLE_EQ(d.frequency_hz, 5.0);
  EXPECT_DOUBLE_EQ(d.damping_ratio, 0.5);
  ASSERT_EQ(d.solvers.size(), kAllChainSolvers.size());
  for (const ChainSolverSettings& s : d.solvers) {
    SCOPED_TRACE(chain_solver_name(s.solver));
    EXPECT_DOUBLE_EQ(s.h, 1.0 / 120.0);  // the engine step is the substep
    EXPECT_EQ(s.count, chain_default_count(s.solver));
    EXPECT_EQ(s.warm_start, chain_default_warm_start(s.solver));
    EXPECT_FALSE(s.linear_damping);
    EXPECT_EQ(s.collision_steps, 1);
  }
}

TEST(TuneChain, EachSolverCountsWhatItsEngineIterates) {
  TuneRequest q = chain_tune_request();
  set_engine_setting(q, "box2d_v2_4", "velocityIterations", 3);
  set_engine_setting(q, "box2d_v3", "subStepCount", 6);
  set_engine_setting(q, "box2d_v3", "enableWarmStarting", 0);
  set_engine_setting(q, "jolt", "numVelocitySteps", 7);
  set_engine_setting(q, "jolt", "collisionSteps", 2);
  // Rapier's additional iterations run the same joint solve as its solver iterations.
  set_engine_setting(q, "rapier", "numSolverIterations", 2);
  set_engine_setting(q, "rapier", "additionalSolverIterations", 3);
  const ChainDesignRequest d = design_of(q);
  EXPECT_EQ(solver_of(d, ChainSolver::box2d_v2_4).count, 3);
  EXPECT_TRUE(solver_of(d, ChainSolver::box2d_v2_4).warm_start);
  EXPECT_EQ(solver_of(d, ChainSolver::box2d_v3).count, 6);
  EXPECT_FALSE(solver_of(d, ChainSolver::box2d_v3).warm_start);
  EXPECT_EQ(solver_of(d, ChainSolver::jolt).count, 7);
  EXPECT_EQ(solver_of(d, ChainSolver::jolt).collision_steps, 2);
  EXPECT_EQ(solver_of(d, ChainSolver::rapier).count, 5);
  EXPECT_FALSE(solver_of(d, ChainSolver::rapier).warm_start);
}

TEST(TuneChain, JoltsLinearDampingCountsOnlyWhenTheUserTypedJoltSettings) {
  TuneRequest q = chain_tune_request();
  EXPECT_FALSE(solver_of(design_of(q), ChainSolver::jolt).linear_damping);
  set_engine_setting(q, "jolt", "linearDamping", 0.3);
  const ChainSolverSettings jolt = solver_of(design_of(q), ChainSolver::jolt);
  ASSERT_TRUE(jolt.linear_damping);
  EXPECT_DOUBLE_EQ(*jolt.linear_damping, 0.3);
}

TEST(TuneChain, TheJointsTakeTheClampedFrequency) {
  TuneRequest q = chain_tune_request();
  q.mode = SoftMode::exact;  // exact softness clamps at the step's Nyquist frequency
  q.frequency_hz = 1000.0;   // far past the 60 Hz Nyquist frequency of a 120 Hz step
  const TuneResult r = tune(q);
  ASSERT_LT(r.frequency_hz, 1000.0);
  const ChainDesignRequest d = chain_design_request(q, r);
  EXPECT_DOUBLE_EQ(d.frequency_hz, r.frequency_hz);
  EXPECT_DOUBLE_EQ(d.damping_ratio, r.damping_ratio);
}

TEST(TuneChain, OnlyTheAskedSolversAreDesigned) {
  TuneRequest q = chain_tune_request();
  q.chain->solvers = {ChainSolver::rapier, ChainSolver::box2d_v3};
  const ChainDesignRequest d = design_of(q);
  ASSERT_EQ(d.solvers.size(), 2u);
  EXPECT_EQ(d.solvers[0].solver, ChainSolver::rapier);
  EXPECT_EQ(d.solvers[1].solver, ChainSolver::box2d_v3);
}

}  // namespace
}  // namespace softtune
