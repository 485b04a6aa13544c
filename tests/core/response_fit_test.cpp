// The response fit against synthetic signals with known answers: analytic oscillator trajectories
// (core/analytic.h) sampled at a fixed rate, with offsets and noise.
#include "softtune/response_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "softtune/analytic.h"

namespace softtune {
namespace {

std::vector<double> oscillator_samples(double f_hz, double zeta, double rate_hz, double seconds, double x0, double offset) {
  std::vector<double> x;
  const double omega = 2.0 * std::numbers::pi * f_hz;
  for (int n = 0; n <= static_cast<int>(seconds * rate_hz); ++n) {
    x.push_back(offset + analytic_state({x0, 0.0}, omega, zeta, n / rate_hz).x);
  }
  return x;
}

struct Case {
  double f_hz, zeta;
};

class FitsKnownOscillator : public ::testing::TestWithParam<Case> {};

TEST_P(FitsKnownOscillator, RecoversFrequencyDampingAndEquilibrium) {
  const auto [f, zeta] = GetParam();
  const auto x = oscillator_samples(f, zeta, 60.0, 4.0, 0.05, 2.98);
  const ResponseFit fit = fit_response(x, 1.0 / 60.0);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio && fit.equilibrium);
  EXPECT_NEAR(*fit.frequency_hz / f, 1.0, 1e-6);
  EXPECT_NEAR(*fit.damping_ratio, zeta, 1e-6);
  EXPECT_NEAR(*fit.equilibrium, 2.98, 1e-6);
  EXPECT_LT(*fit.residual, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(UnderCriticalOver, FitsKnownOscillator,
                         ::testing::Values(Case{1.0, 0.0}, Case{1.0, 0.05}, Case{2.0, 0.5}, Case{0.7, 0.9}, Case{1.5, 1.0},
                                           Case{1.0, 2.0}, Case{12.0, 0.3}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           char name[64];
                           std::snprintf(name, sizeof name, "f%03d_zeta%03d", static_cast<int>(info.param.f_hz * 10),
                                         static_cast<int>(info.param.zeta * 100));
                           return std::string(name);
                         });

TEST(ResponseFit, OvershootMatchesTheClosedForm) {
  // Released from rest, an under-damped oscillator swings past equilibrium by exp(-pi zeta / sqrt(1 - zeta^2)).
  for (double zeta : {0.1, 0.3, 0.5, 0.7}) {
    const auto x = oscillator_samples(1.0, zeta, 2000.0, 3.0, 1.0, 0.0);
    const ResponseFit fit = fit_response(x, 1.0 / 2000.0);
    ASSERT_TRUE(fit.overshoot);
    EXPECT_NEAR(*fit.overshoot, std::exp(-std::numbers::pi * zeta / std::sqrt(1.0 - zeta * zeta)), 1e-4) << zeta;
  }
  // Critically and over-damped responses never cross equilibrium.
  EXPECT_NEAR(*fit_response(oscillator_samples(1.0, 1.0, 600.0, 3.0, 1.0, 0.0), 1.0 / 600.0).overshoot, 0.0, 1e-9);
}

TEST(ResponseFit, SettleIndexOfAnExponentialDecay) {
  // x = exp(-t / tau) enters the 2 % band at t = tau ln 50.
  const double tau = 0.25, rate = 100.0;
  std::vector<double> x;
  for (int n = 0; n < 300; ++n) x.push_back(std::exp(-n / rate / tau));
  const auto settle = settle_index(x, 0.0, kSettleBand);
  ASSERT_TRUE(settle);
  EXPECT_EQ(*settle, static_cast<int>(std::ceil(tau * std::log(50.0) * rate)));
  // Undamped: never settles.
  EXPECT_FALSE(settle_index(oscillator_samples(1.0, 0.0, 60.0, 3.0, 1.0, 0.0), 0.0, kSettleBand));
}

TEST(ResponseFit, ToleratesNoise) {
  auto x = oscillator_samples(1.5, 0.1, 60.0, 5.0, 1.0, 0.0);
  // Deterministic pseudo-noise, 1e-4 of the amplitude.
  unsigned state = 12345;
  for (double& v : x) {
    state = state * 1103515245u + 12345u;
    v += 1e-4 * ((state >> 16 & 0x7fff) / 16383.5 - 1.0);
  }
  const ResponseFit fit = fit_response(x, 1.0 / 60.0);
  ASSERT_TRUE(fit.frequency_hz && fit.damping_ratio);
  EXPECT_NEAR(*fit.frequency_hz / 1.5, 1.0, 0.005);
  EXPECT_NEAR(*fit.damping_ratio, 0.1, 0.01);
}

TEST(ResponseFit, UndefinedInputsGiveEmptyFields) {
  EXPECT_FALSE(fit_response({1, 2, 3}, 0.01).frequency_hz);                        // too few samples
  EXPECT_FALSE(fit_response(std::vector<double>(50, 1.0), 0.01).frequency_hz);     // no motion
  auto x = oscillator_samples(1.0, 0.2, 60.0, 2.0, 1.0, 0.0);
  x[10] = std::nan("");
  const ResponseFit fit = fit_response(x, 1.0 / 60.0);
  EXPECT_FALSE(fit.frequency_hz);
  EXPECT_FALSE(fit.overshoot);
  EXPECT_FALSE(fit_response(oscillator_samples(1.0, 0.2, 60.0, 2.0, 1.0, 0.0), 0.0).frequency_hz);  // h = 0
}

}  // namespace
}  // namespace softtune
