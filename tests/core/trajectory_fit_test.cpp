// fit_trajectory_poles against synthetic signals with known poles.
#include "softtune/trajectory_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace softtune {
namespace {

// x[n] = e^(-sigma n dt) cos(wd n dt): poles exp((-sigma +- i wd) dt), omega = |s|, zeta = sigma / omega.
TEST(TrajectoryFit, RecoversDampedOscillation) {
  const double omega = 2.0 * std::numbers::pi * 3.0, zeta = 0.2, dt = 1.0 / 50.0;
  const double sigma = zeta * omega, wd = omega * std::sqrt(1.0 - zeta * zeta);
  std::vector<double> x;
  for (int n = 0; n < 40; ++n) x.push_back(std::exp(-sigma * n * dt) * std::cos(wd * n * dt + 0.3));
  const auto fit = fit_trajectory_poles(x, dt);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(*fit->frequency_hz, 3.0, 1e-9);
  EXPECT_NEAR(*fit->damping_ratio, 0.2, 1e-9);
  EXPECT_NEAR(fit->spectral_radius, std::exp(-sigma * dt), 1e-12);
}

TEST(TrajectoryFit, GrowingSignalHasRadiusAboveOne) {
  std::vector<double> x;
  for (int n = 0; n < 30; ++n) x.push_back(std::pow(1.01, n) * std::cos(0.5 * n));
  const auto fit = fit_trajectory_poles(x, 0.01);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->spectral_radius, 1.01, 1e-12);
}

TEST(TrajectoryFit, OneModeGivesRealPoleAndNoFrequency) {
  std::vector<double> x;
  for (int n = 0; n < 20; ++n) x.push_back(std::pow(0.7, n));
  const auto fit = fit_trajectory_poles(x, 0.1);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->spectral_radius, 0.7, 1e-12);
  EXPECT_FALSE(fit->frequency_hz);
}

TEST(TrajectoryFit, RefusesShortZeroOrNonFinite) {
  EXPECT_FALSE(fit_trajectory_poles(std::vector<double>{1, 2, 3}, 0.1));
  EXPECT_FALSE(fit_trajectory_poles(std::vector<double>(10, 0.0), 0.1));
  EXPECT_FALSE(fit_trajectory_poles(std::vector<double>{1, 2, NAN, 3, 4}, 0.1));
}

}  // namespace
}  // namespace softtune
