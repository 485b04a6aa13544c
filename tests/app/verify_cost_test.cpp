#include "app/verify_cost.h"

#include <gtest/gtest.h>

#include "app/budgets.h"

using softtune::codec::decode_verify_request;

TEST(VerifyCost, EveryEngineAtTheStepLimitIsOverOneAtTheDefaultFits) {
  const nlohmann::json base = {{"frequency_hz", 2}, {"damping_ratio", 0.1}, {"effective_mass", 1}};
  nlohmann::json one = base;
  one["engines"] = {"box2d_v2_4"};
  EXPECT_LT(softtune::app::verify_cost(decode_verify_request(one)).cpu_seconds, softtune::app::budgets::kCpuSeconds);
  nlohmann::json all = base;
  all["engines"] = {"box2d_v2_4", "ode", "bullet", "mujoco"};
  all["fps"] = 4000;
  all["duration_s"] = 50;
  const auto over = softtune::app::verify_cost(decode_verify_request(all));
  EXPECT_GT(over.cpu_seconds, softtune::app::budgets::kCpuSeconds);
  EXPECT_EQ(over.fields.front(), "fps");
}
