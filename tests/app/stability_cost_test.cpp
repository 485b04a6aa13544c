#include "app/stability_cost.h"

#include <gtest/gtest.h>

#include "app/budgets.h"

using softtune::codec::decode_stability_request;

// The default sweep is the heaviest request inside the budget; the request that ran 33.8 s is not.
TEST(StabilityCost, DefaultSweepFitsAndTheHalfMinuteOneDoesNot) {
  const auto fits = softtune::app::stability_cost(decode_stability_request(nlohmann::json()));
  EXPECT_LT(fits.cpu_seconds, softtune::app::budgets::kCpuSeconds);
  EXPECT_LT(fits.peak_bytes, softtune::app::budgets::kPeakBytes);
  const auto over = softtune::app::stability_cost(decode_stability_request({{"observe_steps", 91835}}));
  EXPECT_GT(over.cpu_seconds, 10 * softtune::app::budgets::kCpuSeconds);
  ASSERT_FALSE(over.fields.empty());
  EXPECT_EQ(over.fields.front(), "observe_steps");
}

// The bound counts the cases run_sweep runs when no frequency case is above max_stiffness.
TEST(StabilityCost, CaseBoundIsTheSweepsOwnCount) {
  const auto q = decode_stability_request({{"steps", {0.01, 0.001}}, {"masses", {1, 2, 3}}, {"damping_ratios", {0, 1}},
                                           {"frequency_ratios", {0.01, 0.1}}, {"stiffnesses", {10}},
                                           {"max_stiffness", 1e15}, {"chain", false}});
  EXPECT_EQ(softtune::codec::grid_case_bound(q.sweep), softtune::run_sweep(q.sweep).summary.cases);
  EXPECT_EQ(softtune::app::chain_case_count(q), 0u);
}
