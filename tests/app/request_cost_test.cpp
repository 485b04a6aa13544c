#include "app/request_cost.h"

#include <gtest/gtest.h>

#include "app/budgets.h"
#include "codec/problem.h"

using softtune::app::RequestCost;
using softtune::app::require_within_budget;

TEST(RequestCost, WithinTheBudgetPasses) {
  EXPECT_NO_THROW(require_within_budget({softtune::app::budgets::kCpuSeconds, softtune::app::budgets::kPeakBytes, {"x"}, "w"}));
}

TEST(RequestCost, OverEitherBudgetIsA422NamingTheDrivers) {
  for (const RequestCost& cost : {RequestCost{5.0, 1.0, {"observe_steps", "masses"}, "many cases"},
                                  RequestCost{0.1, 1e9, {"observe_steps", "masses"}, "many cases"}}) {
    try {
      require_within_budget(cost);
      FAIL();
    } catch (const softtune::codec::Problem& p) {
      EXPECT_EQ(p.status, 422);
      EXPECT_EQ(p.field, "observe_steps");
      EXPECT_NE(p.detail.find("observe_steps, masses"), std::string::npos) << p.detail;
      const nlohmann::json j = softtune::codec::problem_json(p);
      EXPECT_EQ(j["fields"], nlohmann::json({"observe_steps", "masses"}));
      EXPECT_EQ(j["budget_cpu_seconds"], softtune::app::budgets::kCpuSeconds);
      EXPECT_EQ(j["estimated_cpu_seconds"], cost.cpu_seconds);
      EXPECT_EQ(j["type"], "/problems/request-over-budget");
    }
  }
}
