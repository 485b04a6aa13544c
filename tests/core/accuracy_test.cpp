// The work-precision report against closed forms, the identity soft == implicit Euler, the blow-up
// verdicts, deterministic timing and the recommendation logic.
#include "softtune/accuracy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <memory>
#include <numbers>

namespace softtune {
namespace {

constexpr double kPi = std::numbers::pi;

// A clock that advances 1 microsecond per read: every timed batch takes exactly 1 us.
SecondsClock fake_clock() {
  auto t = std::make_shared<double>(0.0);
  return [t] { return *t += 1e-6; };
}

AccuracySettings ten_hz(double zeta) {
  AccuracySettings s;
  s.mass = 2.0;
  s.omega = 2.0 * kPi * 10.0;
  s.damping_ratio = zeta;
  s.duration_s = 0.3;
  s.step_rates_hz = {60.0, 240.0};
  s.clock = fake_clock();
  return s;
}

const AccuracyRow& find(const AccuracyReport& r, std::string_view method, double fps, int substeps) {
  for (const AccuracyRow& row : r.rows) {
    if (row.method == method && row.fps == fps && row.substeps == substeps) return row;
  }
  ADD_FAILURE() << "no row " << method << " " << fps << " " << substeps;
  return r.rows.front();
}

TEST(Accuracy, RowsCoverEveryMethodRateAndSubstep) {
  const AccuracyReport r = run_accuracy(ten_hz(0.0));
  // Per rate: explicit, semi-implicit, implicit, and soft, soft_exact at 1, 2, 4, 8 substeps.
  EXPECT_EQ(r.rows.size(), 2u * (3 + 2 * 4));
  EXPECT_DOUBLE_EQ(r.duration_s, 0.3);
  EXPECT_EQ(find(r, "soft", 60, 8).h, 1.0 / 480.0);
  EXPECT_EQ(find(r, "soft", 60, 1).frames, 18);
}

// Implicit Euler, zeta = 0, w = omega h: z = (1 +- i w) / (1 + w^2), so x_n = r^n cos(n theta) with
// r = 1 / sqrt(1 + w^2), theta = atan(w). The error against cos(omega t) is computed here independently.
TEST(Accuracy, ImplicitEulerErrorMatchesClosedForm) {
  const AccuracySettings s = ten_hz(0.0);
  const AccuracyReport r = run_accuracy(s);
  for (double fps : s.step_rates_hz) {
    const double h = 1.0 / fps, w = s.omega * h;
    const double radius = 1.0 / std::sqrt(1.0 + w * w), theta = std::atan(w);
    const AccuracyRow& row = find(r, "implicit_euler", fps, 1);
    double max_error = 0.0, sum_sq = 0.0;
    for (int n = 1; n <= row.frames; ++n) {
      const double e = std::abs(std::pow(radius, n) * std::cos(n * theta) - std::cos(s.omega * n * h));
      max_error = std::max(max_error, e);
      sum_sq += e * e;
    }
    ASSERT_TRUE(row.max_error);
    EXPECT_NEAR(*row.max_error, max_error, 1e-12);
    EXPECT_NEAR(*row.rms_error, std::sqrt(sum_sq / row.frames), 1e-12);
    EXPECT_NEAR(*row.pole_frequency_hz, std::sqrt(std::log(radius) * std::log(radius) + theta * theta) / (2 * kPi * h),
                1e-9);
    EXPECT_FALSE(row.blew_up);
  }
}

TEST(Accuracy, SoftEqualsImplicitEulerToRoundOff) {
  for (double zeta : {0.0, 0.5, 1.0, 10.0}) {
    const AccuracyReport r = run_accuracy(ten_hz(zeta));
    for (double fps : {60.0, 240.0}) {
      const AccuracyRow& soft = find(r, "soft", fps, 1);
      const AccuracyRow& implicit = find(r, "implicit_euler", fps, 1);
      ASSERT_EQ(soft.positions.size(), implicit.positions.size());
      for (std::size_t n = 0; n < soft.positions.size(); ++n) EXPECT_NEAR(soft.positions[n], implicit.positions[n], 1e-13);
      EXPECT_NEAR(*soft.max_error, *implicit.max_error, 1e-13);
    }
  }
}

// Explicit Euler, zeta = 0: |z| = sqrt(1 + w^2) > 1 at every h: it grows, and the fitted trajectory
// poles give the closed-form frequency |ln z| / h.
TEST(Accuracy, ExplicitEulerGrowsAtZeroDamping) {
  const AccuracySettings s = ten_hz(0.0);
  const AccuracyReport r = run_accuracy(s);
  for (double fps : s.step_rates_hz) {
    const AccuracyRow& row = find(r, "explicit_euler", fps, 1);
    EXPECT_TRUE(row.blew_up) << fps;
    EXPECT_FALSE(row.max_error);
    const double w = s.omega / fps;
    const double expected = std::abs(std::complex<double>(0.5 * std::log(1 + w * w), std::atan(w))) * fps / (2 * kPi);
    ASSERT_TRUE(row.trajectory_frequency_hz);
    EXPECT_NEAR(*row.trajectory_frequency_hz, expected, 1e-8);
  }
}

// Semi-implicit Euler undamped is bounded for omega h < 2 (60 fps: 1.05) and grows beyond (30 fps: 2.09).
TEST(Accuracy, SemiImplicitBlowsUpOnlyBeyondItsLimit) {
  AccuracySettings s = ten_hz(0.0);
  s.step_rates_hz = {30.0, 60.0};
  const AccuracyReport r = run_accuracy(s);
  EXPECT_TRUE(find(r, "semi_implicit_euler", 30, 1).blew_up);
  EXPECT_FALSE(find(r, "semi_implicit_euler", 60, 1).blew_up);
}

// Exact mode: the trajectory's own poles are the asked 10 Hz and zeta, at every rate and substep count.
TEST(Accuracy, SoftExactTrajectoryHasTheAskedPoles) {
  const AccuracyReport r = run_accuracy(ten_hz(0.5));
  for (int n : {1, 2, 4, 8}) {
    const AccuracyRow& row = find(r, "soft_exact", 60, n);
    ASSERT_TRUE(row.trajectory_frequency_hz);
    EXPECT_NEAR(*row.trajectory_frequency_hz, 10.0, 1e-6);
    EXPECT_NEAR(*row.trajectory_damping_ratio, 0.5, 1e-6);
  }
}

TEST(Accuracy, MoreSubstepsReduceTheSoftError) {
  const AccuracyReport r = run_accuracy(ten_hz(0.0));
  EXPECT_LT(*find(r, "soft", 60, 8).max_error, *find(r, "soft", 60, 2).max_error);
  EXPECT_LT(*find(r, "soft_exact", 60, 8).max_error, *find(r, "soft_exact", 60, 1).max_error);
}

// With 1 us per batch, cost = 1e-6 / runs_per_batch / simulated seconds, runs_per_batch =
// ceil(min_steps_per_batch / steps).
TEST(Accuracy, TimingUsesTheInjectedClock) {
  AccuracySettings s = ten_hz(0.0);
  s.min_steps_per_batch = 1;
  const AccuracyReport r = run_accuracy(s);
  for (const AccuracyRow& row : r.rows) {
    EXPECT_NEAR(row.cpu_seconds_per_sim_second, 1e-6 / (row.frames / row.fps), 1e-15) << row.method;
  }
  s.min_steps_per_batch = 4096;
  const AccuracyReport report = run_accuracy(s);
  const AccuracyRow& row = find(report, "soft", 60, 1);
  const double runs = std::ceil(4096.0 / 18.0);
  EXPECT_NEAR(row.cpu_seconds_per_sim_second, 1e-6 / runs / 0.3, 1e-15);
}

AccuracyRow synthetic(std::string method, double cost, std::optional<double> error, bool blew_up = false) {
  AccuracyRow r;
  r.method = std::move(method);
  r.cpu_seconds_per_sim_second = cost;
  r.max_error = error;
  r.blew_up = blew_up;
  return r;
}

TEST(Recommendation, CheapestRowWithinBudget) {
  const std::vector<AccuracyRow> rows = {synthetic("a", 1.0, 0.2), synthetic("b", 2.0, 0.04), synthetic("c", 5.0, 0.001),
                                         synthetic("d", 0.5, std::nullopt, true)};
  const Recommendation r = recommend(rows, 0.05);
  ASSERT_TRUE(r.row);
  EXPECT_EQ(*r.row, 1u);
  EXPECT_EQ(r.rows_meeting_budget, 2u);
  EXPECT_EQ(*r.most_accurate, 2u);
}

TEST(Recommendation, NearTieGoesToTheMoreAccurate) {
  const std::vector<AccuracyRow> rows = {synthetic("a", 1.00, 0.04), synthetic("b", 1.05, 0.01), synthetic("c", 1.2, 0.0)};
  EXPECT_EQ(*recommend(rows, 0.05).row, 1u);
}

TEST(Recommendation, NoneMeetsTheBudget) {
  const std::vector<AccuracyRow> rows = {synthetic("a", 1.0, 0.2), synthetic("b", 2.0, 0.1)};
  const Recommendation r = recommend(rows, 0.05);
  EXPECT_FALSE(r.row);
  EXPECT_EQ(r.rows_meeting_budget, 0u);
  EXPECT_EQ(*r.most_accurate, 1u);
}

TEST(Recommendation, ReportRecommendsARowThatMeetsTheBudget) {
  AccuracySettings s = ten_hz(0.5);
  s.error_budget = 0.02;
  const AccuracyReport r = run_accuracy(s);
  ASSERT_TRUE(r.recommendation.row);
  const AccuracyRow& row = r.rows[*r.recommendation.row];
  EXPECT_LE(*row.max_error, 0.02);
  EXPECT_FALSE(row.blew_up);
}

TEST(Accuracy, TrajectoryErrorOfTheExactSolutionIsZero) {
  const double omega = 5.0, zeta = 0.3, dt = 0.01;
  std::vector<double> x;
  for (int n = 0; n < 50; ++n) {
    const double wd = omega * std::sqrt(1 - zeta * zeta);
    x.push_back(std::exp(-zeta * omega * n * dt) * (std::cos(wd * n * dt) + zeta * omega / wd * std::sin(wd * n * dt)));
  }
  const TrajectoryError e = trajectory_error(x, dt, omega, zeta);
  EXPECT_LT(e.max_error, 1e-14);
}

}  // namespace
}  // namespace softtune
