// Scene expectations (expectations.cpp): a check passes inside its bounds and fails outside them.
#include "softtune/scene/expectations.h"

#include <gtest/gtest.h>

#include "scene_builders.h"

namespace softtune::scene {
namespace {

using namespace test;

TEST(Expectations, FailWhenTheFigureIsOutsideOrUndefined) {
  Scene s = buddhas({0.0, 0.95});
  s.expectations.push_back({"hanger0", Metric::frequency_error, std::nullopt, 0.03, std::nullopt, "", {}, {}});
  s.expectations.push_back({"hanger1", Metric::frequency_error, 0.5, std::nullopt, MassModel::box2d_reduced, "", {}, {}});
  s.expectations.push_back({"", Metric::finite, std::nullopt, std::nullopt, std::nullopt, "", {}, {}});
  CheckResult ok = check_scene(s);
  EXPECT_TRUE(ok.passed);
  EXPECT_EQ(ok.runs.size(), 2u);
  EXPECT_TRUE(ok.runs.front().stages.contains(Stage::expectations));

  s.expectations.push_back({"hanger1", Metric::frequency_error, std::nullopt, 0.03, MassModel::box2d_reduced, "", {}, {}});
  const CheckResult bad = check_scene(s);
  EXPECT_FALSE(bad.passed);
  EXPECT_FALSE(bad.results.back().passed);
}

}  // namespace
}  // namespace softtune::scene
