// The one bisection routine every stability limit goes through, against closed forms and against a dense
// scan: semi-implicit and explicit Euler's Jury limits, the soft constraint's "no limit", the marginal band.
#include "softtune/stability_limit.h"

#include <gtest/gtest.h>

#include <cmath>

#include "softtune/stability_sweep.h"

namespace softtune {
namespace {

// A dense scan's answer: the first unstable point of `points` log-spaced points (empty: none).
std::optional<double> first_unstable_by_dense_scan(const SpectralRadiusOf& rho, double lo, double hi, int points) {
  for (double p : log_scan(lo, hi, points)) {
    if (classify_spectral_radius(rho(p)) == Verdict::unstable) return p;
  }
  return std::nullopt;
}

SpectralRadiusOf radius_of(Method m, double zeta) {
  return [m, zeta](double omega_h) {
    std::complex<double> z1, z2;
    eigenvalues_2x2(step_matrix(m, make_step_model(1.0, omega_h, zeta, 1.0)), z1, z2);
    return std::max(std::abs(z1), std::abs(z2));
  };
}

// rho = p / 3 crosses 1 + band at p = 3 (1 + band): the routine's own bracket on a known line.
TEST(StabilityLimit, BisectsAKnownCrossingToTheTolerance) {
  const SpectralRadiusOf rho = [](double p) { return p / 3.0; };
  const StabilityLimit l = find_stability_limit(rho, log_scan(0.1, 100.0, 16));
  ASSERT_EQ(l.kind, LimitKind::found);
  const double crossing = 3.0 * (1.0 + kMarginalBand);
  EXPECT_LE(*l.stable_side, crossing);
  EXPECT_GT(*l.unstable_side, crossing);
  EXPECT_LE(*l.unstable_side / *l.stable_side - 1.0, kLimitRelativeTolerance);
  EXPECT_NE(classify_spectral_radius(l.stable_side_radius), Verdict::unstable);
  EXPECT_EQ(classify_spectral_radius(l.unstable_side_radius), Verdict::unstable);
}

TEST(StabilityLimit, SaysWhenNoLimitIsInRangeOrTheRangeStartsUnstable) {
  const std::vector<double> scan = log_scan(0.1, 10.0, 9);
  const StabilityLimit none = find_stability_limit([](double) { return 0.5; }, scan);
  EXPECT_EQ(none.kind, LimitKind::none_in_range);
  EXPECT_DOUBLE_EQ(*none.stable_side, 10.0);
  EXPECT_FALSE(none.unstable_side);
  const StabilityLimit below = find_stability_limit([](double) { return 2.0; }, scan);
  EXPECT_EQ(below.kind, LimitKind::unstable_at_lowest);
  EXPECT_FALSE(below.stable_side);
  EXPECT_DOUBLE_EQ(*below.unstable_side, 0.1);
}

// Semi-implicit Euler: omega h < 2 (sqrt(zeta^2 + 1) - zeta); explicit Euler: omega h < 2 zeta (zeta <= 1)
// or 2 (zeta - sqrt(zeta^2 - 1)). The bracket holds the closed form and the dense scan's first unstable
// point lies just above its stable side.
TEST(StabilityLimit, BracketHoldsTheClosedFormAndMatchesADenseScan) {
  for (Method m : {Method::semi_implicit_euler, Method::explicit_euler}) {
    for (double zeta : {1e-3, 0.1, 0.5, 1.0, 10.0}) {
      const StepLimit l = find_step_limit(m, zeta);
      ASSERT_EQ(l.omega_h.kind, LimitKind::found) << method_name(m) << " " << zeta;
      const double closed = m == Method::semi_implicit_euler
                                ? 2.0 * (std::sqrt(zeta * zeta + 1.0) - zeta)
                                : (zeta <= 1.0 ? 2.0 * zeta : 2.0 * (zeta - std::sqrt(zeta * zeta - 1.0)));
      EXPECT_LE(*l.omega_h.stable_side, closed * (1.0 + 1e-9)) << method_name(m) << " " << zeta;
      EXPECT_GE(*l.omega_h.unstable_side, closed) << method_name(m) << " " << zeta;
      EXPECT_LE(*l.omega_h.unstable_side / *l.omega_h.stable_side - 1.0, kLimitRelativeTolerance);
      // Dense scan over the bracketing decade, 4000 points (spacing 0.06 %).
      const auto dense = first_unstable_by_dense_scan(radius_of(m, zeta), closed / 3.0, closed * 3.0, 4000);
      ASSERT_TRUE(dense);
      EXPECT_GT(*dense, *l.omega_h.stable_side);
      EXPECT_LE(*dense, *l.omega_h.unstable_side * 1.001);
    }
  }
}

// The soft constraint (standard and exact) and implicit Euler: no limit anywhere in 1e-6..1e6 rad, and a
// dense scan finds no unstable point either.
TEST(StabilityLimit, SoftConstraintHasNoLimitInRange) {
  for (Method m : {Method::soft, Method::soft_exact, Method::implicit_euler}) {
    for (double zeta : {0.0, 0.1, 1.0, 1000.0}) {
      const StepLimit l = find_step_limit(m, zeta);
      EXPECT_EQ(l.omega_h.kind, LimitKind::none_in_range) << method_name(m) << " " << zeta;
      EXPECT_FALSE(l.closed_form_omega_h);
      EXPECT_FALSE(first_unstable_by_dense_scan(radius_of(m, zeta), kStepLimitLowest, kStepLimitHighest, 2000))
          << method_name(m) << " " << zeta;
    }
  }
}

// The marginal band counts as stable, as the sweep counts it: semi-implicit Euler undamped is marginal up to
// omega h = 2; explicit Euler undamped, |z| = sqrt(1 + (omega h)^2), is within the band below
// omega h = sqrt(2 band) (its closed form, 0, is the exact-arithmetic answer).
TEST(StabilityLimit, MarginalBandIsTheStableSide) {
  const StepLimit semi = find_step_limit(Method::semi_implicit_euler, 0.0);
  ASSERT_EQ(semi.omega_h.kind, LimitKind::found);
  EXPECT_EQ(classify_spectral_radius(semi.omega_h.stable_side_radius), Verdict::marginal);
  EXPECT_LE(*semi.omega_h.stable_side, 2.0);
  EXPECT_GE(*semi.omega_h.unstable_side, 2.0);
  const StepLimit expl = find_step_limit(Method::explicit_euler, 0.0);
  ASSERT_EQ(expl.omega_h.kind, LimitKind::found);
  const double band_edge = std::sqrt(2.0 * kMarginalBand);
  EXPECT_NEAR(*expl.omega_h.stable_side / band_edge, 1.0, 2e-3);
}

}  // namespace
}  // namespace softtune
