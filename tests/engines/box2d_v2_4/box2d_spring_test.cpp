// Box2D 2.4's distance joint is the soft constraint: the talk's identity through a real engine (float).
#include "box2d_spring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "softtune/accuracy.h"
#include "softtune/methods.h"

namespace softtune {
namespace {

void expect_matches_soft(double mass, double hz, double zeta, double fps) {
  const double omega = 2.0 * std::numbers::pi * hz, h = 1.0 / fps;
  const StepModel model = make_step_model(mass, omega, zeta, h);
  const int steps = 60;
  const std::vector<double> engine = run_box2d_spring(model.spring, 1.0, h, steps);
  ASSERT_EQ(engine.size(), static_cast<std::size_t>(steps + 1));
  State s{1.0, 0.0};
  for (int n = 1; n <= steps; ++n) {
    s = step(Method::soft, s, model);
    EXPECT_NEAR(engine[n], s.x, 2e-6) << "step " << n << " at " << hz << " Hz, zeta " << zeta;
  }
}

TEST(Box2DSpring, MatchesSoftConstraintToFloatPrecision) {
  expect_matches_soft(1.0, 10.0, 0.0, 60.0);
  expect_matches_soft(2.0, 10.0, 0.5, 60.0);
  expect_matches_soft(0.5, 2.0, 1.0, 120.0);
  expect_matches_soft(5.0, 25.0, 0.1, 240.0);
}

TEST(Box2DSpring, RowInTheReportAgreesWithSoft) {
  AccuracySettings s;
  s.omega = 2.0 * std::numbers::pi * 10.0;
  s.duration_s = 0.3;
  s.step_rates_hz = {60.0};
  s.soft_substeps = {1};
  s.timing_repeats = 1;
  s.engine = EngineRunner{kBox2DRowName, run_box2d_spring};
  const AccuracyReport r = run_accuracy(s);
  const AccuracyRow* soft = nullptr;
  const AccuracyRow* box = nullptr;
  for (const AccuracyRow& row : r.rows) {
    if (row.method == "soft") soft = &row;
    if (row.method == kBox2DRowName) box = &row;
  }
  ASSERT_TRUE(soft && box);
  EXPECT_FALSE(box->core_method);
  EXPECT_NEAR(*box->max_error, *soft->max_error, 1e-6);
  EXPECT_NEAR(*box->trajectory_frequency_hz, *soft->pole_frequency_hz, 1e-4);
}

}  // namespace
}  // namespace softtune
