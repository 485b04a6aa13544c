#include "app/accuracy_cost.h"

#include <gtest/gtest.h>

#include "app/budgets.h"

using softtune::codec::decode_accuracy_request;

TEST(AccuracyCost, DefaultReportFitsALongRepeatedOneDoesNot) {
  const nlohmann::json base = {{"frequency_hz", 10}, {"oscillation", "free"}, {"effective_mass", 1}};
  const auto fits = softtune::app::accuracy_cost(decode_accuracy_request(base), true, true);
  EXPECT_LT(fits.cpu_seconds, softtune::app::budgets::kCpuSeconds);
  nlohmann::json heavy = base;
  heavy["step_rates"] = {10000, 20000};
  heavy["soft_substeps"] = {1};
  heavy["duration_s"] = 50;
  heavy["timing_repeats"] = 51;
  const auto over = softtune::app::accuracy_cost(decode_accuracy_request(heavy), true, false);
  EXPECT_GT(over.cpu_seconds, softtune::app::budgets::kCpuSeconds);
  ASSERT_FALSE(over.fields.empty());
  EXPECT_EQ(over.fields.front(), "duration_s");
  EXPECT_NE(std::find(over.fields.begin(), over.fields.end(), "timing_repeats"), over.fields.end());
}
