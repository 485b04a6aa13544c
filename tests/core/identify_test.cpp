// Identification against recordings with known answers: the analytic oscillator (core/analytic.h) sampled
// at a fixed rate, and every core integrator stepped, whose true poles come from its step matrix
// (discrete_analysis.h, a closed form independent of any fit); then offsets, noise, jitter in the time
// column, non-uniform sampling, held frames, truncation and clipping. Each test prints its identified
// against true values.
#include "softtune/identify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "softtune/analytic.h"
#include "softtune/discrete_analysis.h"
#include "softtune/methods.h"
#include "softtune/response_fit.h"

namespace softtune {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The analytic oscillator released from rest at x0 about `offset`, sampled at the given times.
std::vector<double> analytic_at(const std::vector<double>& t, double f, double zeta, double x0, double offset) {
  std::vector<double> x;
  for (double ti : t) x.push_back(offset + analytic_state({x0, 0.0}, kTwoPi * f, zeta, ti).x);
  return x;
}

std::vector<double> uniform_times(double rate, double seconds) {
  std::vector<double> t;
  for (int n = 0; n <= static_cast<int>(seconds * rate); ++n) t.push_back(n / rate);
  return t;
}

bool has(const std::vector<IdentifyVerdict>& list, IdentifyVerdict v) {
  return std::find(list.begin(), list.end(), v) != list.end();
}

void print_row(const char* what, double f_true, double z_true, const MotionFit& fit) {
  std::printf("  %-44s true %8.4f Hz zeta %.4f | identified %8.4f Hz zeta %.4f | residual %.2g\n", what, f_true,
              z_true, fit.frequency_hz.value_or(NAN), fit.damping_ratio.value_or(NAN), fit.residual.value_or(NAN));
}

TEST(Identify, AnalyticOscillatorWithOffsetIsExact) {
  for (double f_over_fps : {0.01, 0.05, 0.15, 0.3}) {
    for (double zeta : {0.0, 0.1, 0.5, 0.9, 2.0}) {
      const double f = 60.0 * f_over_fps;
      Recording r{uniform_times(60.0, 4.0), {}};
      r.probes.push_back(analytic_at(r.time_s, f, zeta, 0.05, 2.98));
      const Identification id = identify(r);
      print_row(("analytic f/fps " + std::to_string(f_over_fps) + " zeta " + std::to_string(zeta)).c_str(), f, zeta,
                id.joint);
      // A motion that decays below fit_response's floor (kFitFloor) within 8 samples leaves nothing to fit.
      const double slowest = zeta > 1.0 ? zeta - std::sqrt(zeta * zeta - 1.0) : zeta;
      if (std::exp(-slowest * kTwoPi * f * 8.0 / 60.0) < kFitFloor) {
        EXPECT_TRUE(has(id.verdicts, IdentifyVerdict::too_short)) << f << " " << zeta;
        continue;
      }
      ASSERT_TRUE(id.joint.frequency_hz && id.joint.damping_ratio);
      EXPECT_NEAR(*id.joint.frequency_hz / f, 1.0, 1e-6) << f << " " << zeta;
      EXPECT_NEAR(*id.joint.damping_ratio, zeta, 1e-6) << f << " " << zeta;
      EXPECT_NEAR(id.joint.equilibrium[0], 2.98, 1e-6);
      EXPECT_NEAR(id.sample_rate_hz, 60.0, 1e-9);
      EXPECT_FALSE(id.step_rate_hz);
      EXPECT_EQ(has(id.verdicts, IdentifyVerdict::not_oscillating), zeta >= 1.0);
      EXPECT_FALSE(has(id.verdicts, IdentifyVerdict::too_noisy));
      EXPECT_FALSE(has(id.verdicts, IdentifyVerdict::clipped));
    }
  }
}

// Every integrator's trajectory is exactly a two-pole recurrence: the identified poles are its step
// matrix's eigenvalues, read as frequency and damping ratio by the discrete analysis.
TEST(Identify, EveryIntegratorMatchesItsStepMatrix) {
  for (Method m : kAllMethods) {
    for (double f_over_fps : {0.02, 0.08, 0.2}) {
      for (double zeta : {0.05, 0.5, 1.5}) {
        const double h = 1.0 / 60.0, omega = kTwoPi * 60.0 * f_over_fps;
        const StepModel model = make_step_model(2.0, omega, zeta, h);
        const DiscreteAnalysis truth = analyze(m, model, omega, zeta);
        if (!truth.achieved_frequency_hz || truth.spectral_radius > 1.05) continue;  // blows up, or no reading
        Recording r;
        State s{0.02, 0.0};
        for (int n = 0; n < 240; ++n) {
          r.time_s.push_back(n * h);
          r.probes.resize(1);
          r.probes[0].push_back(s.x - 0.4);
          s = step(m, s, model);
        }
        const Identification id = identify(r);
        print_row((std::string(method_name(m)) + " f/fps " + std::to_string(f_over_fps) + " zeta " +
                   std::to_string(zeta)).c_str(),
                  *truth.achieved_frequency_hz, *truth.achieved_damping_ratio, id.joint);
        ASSERT_TRUE(id.joint.frequency_hz) << method_name(m);
        EXPECT_NEAR(*id.joint.frequency_hz / *truth.achieved_frequency_hz, 1.0, 1e-5) << method_name(m);
        EXPECT_NEAR(*id.joint.damping_ratio, *truth.achieved_damping_ratio, 1e-5) << method_name(m);
        ASSERT_TRUE(id.joint.z1);
        EXPECT_NEAR(std::max(std::abs(*id.joint.z1), std::abs(*id.joint.z2)), truth.spectral_radius, 1e-6);
      }
    }
  }
}

// White noise on the samples biases Prony's equation error towards more damping; the output-error
// refinement removes that bias.
TEST(Identify, NoiseIsAveragedOutAndTooMuchIsFlagged) {
  std::mt19937 rng(19);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double f = 2.0, zeta = 0.1;
  Recording r{uniform_times(60.0, 8.0), {}};
  r.probes.push_back(analytic_at(r.time_s, f, zeta, 1.0, 0.5));
  std::vector<double> clean = r.probes[0];
  for (double& v : r.probes[0]) v += 0.01 * noise(rng);
  const Identification id = identify(r);
  const ResponseFit prony = fit_response(r.probes[0], 1.0 / 60.0);
  print_row("analytic + 1 % noise", f, zeta, id.joint);
  std::printf("  %-44s                               | Prony alone %8.4f Hz zeta %.4f\n", "", prony.frequency_hz.value_or(NAN),
              prony.damping_ratio.value_or(NAN));
  ASSERT_TRUE(id.joint.frequency_hz);
  EXPECT_NEAR(*id.joint.frequency_hz / f, 1.0, 2e-3);
  EXPECT_NEAR(*id.joint.damping_ratio, zeta, 3e-3);
  EXPECT_NEAR(id.joint.equilibrium[0], 0.5, 2e-3);
  EXPECT_FALSE(has(id.verdicts, IdentifyVerdict::too_noisy));

  for (std::size_t i = 0; i < clean.size(); ++i) r.probes[0][i] = clean[i] + 0.5 * noise(rng);
  const Identification noisy = identify(r);
  print_row("analytic + 50 % noise", f, zeta, noisy.joint);
  EXPECT_TRUE(has(noisy.verdicts, IdentifyVerdict::too_noisy));
}

// Noise in the time column alone (a wall clock): the least-squares grid averages it out, no resampling.
TEST(Identify, JitterInTheTimeColumnIsAveragedOut) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.15, 0.15);
  const double f = 3.0, zeta = 0.3, rate = 60.0;
  Recording r{uniform_times(rate, 3.0), {}};
  r.probes.push_back(analytic_at(r.time_s, f, zeta, 0.1, 0.0));
  for (double& t : r.time_s) t += jitter(rng) / rate;
  const Identification id = identify(r);
  print_row("time column +-15 % jitter", f, zeta, id.joint);
  EXPECT_FALSE(id.resampled);
  EXPECT_LT(id.grid_deviation, kIdentifyGridTolerance);
  EXPECT_NEAR(id.sample_rate_hz / rate, 1.0, 1e-3);
  EXPECT_NEAR(*id.joint.frequency_hz / f, 1.0, 1e-3);
  EXPECT_NEAR(*id.joint.damping_ratio, zeta, 2e-3);
}

// Samples truly taken at uneven times (a variable frame rate): resampled onto a uniform grid.
TEST(Identify, NonUniformSamplingIsResampled) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> gap(0.5, 1.5);
  const double f = 1.5, zeta = 0.2, rate = 120.0;
  Recording r;
  for (double t = 0.0; t < 4.0; t += gap(rng) / rate) r.time_s.push_back(t);
  r.probes.push_back(analytic_at(r.time_s, f, zeta, 0.1, 0.0));
  const Identification id = identify(r);
  print_row("uneven sampling, gaps 0.5..1.5 of 1/120 s", f, zeta, id.joint);
  EXPECT_TRUE(id.resampled);
  EXPECT_TRUE(has(id.verdicts, IdentifyVerdict::non_uniform_sampling));
  EXPECT_NEAR(*id.joint.frequency_hz / f, 1.0, 5e-3);
  EXPECT_NEAR(*id.joint.damping_ratio, zeta, 5e-3);
}

// Physics stepped at 50 Hz, recorded every rendered frame at 144 Hz: each step is held for two or three
// frames. The step rate is read back and the poles are the physics step's.
TEST(Identify, HeldFramesRevealTheStepRate) {
  const double step_hz = 50.0, render_hz = 144.0, f = 2.5, zeta = 0.2;
  const double h = 1.0 / step_hz, omega = kTwoPi * f;
  const StepModel model = make_step_model(1.0, omega, zeta, h);
  const DiscreteAnalysis truth = analyze(Method::soft, model, omega, zeta);
  std::vector<double> steps;
  State s{0.05, 0.0};
  for (int n = 0; n < 200; ++n) {
    steps.push_back(s.x);
    s = step(Method::soft, s, model);
  }
  Recording r;
  for (int i = 0; i < 500; ++i) {
    const double t = i / render_hz;
    r.time_s.push_back(t);
    r.probes.resize(1);
    r.probes[0].push_back(steps[static_cast<std::size_t>(std::floor(t * step_hz + 1e-9))]);
  }
  const Identification id = identify(r);
  print_row("soft step at 50 Hz recorded at 144 Hz", *truth.achieved_frequency_hz, *truth.achieved_damping_ratio,
            id.joint);
  ASSERT_TRUE(id.step_rate_hz);
  EXPECT_NEAR(*id.step_rate_hz / step_hz, 1.0, 2e-3);
  EXPECT_NEAR(*id.joint.frequency_hz / *truth.achieved_frequency_hz, 1.0, 3e-3);
  EXPECT_NEAR(*id.joint.damping_ratio, *truth.achieved_damping_ratio, 3e-3);
}

TEST(Identify, TruncatedRecordings) {
  const double f = 5.0, zeta = 0.1;
  Recording full{uniform_times(60.0, 10.0), {}};
  full.probes.push_back(analytic_at(full.time_s, f, zeta, 0.1, 0.0));
  for (std::size_t rows : {600u, 36u, 16u, 10u}) {
    Recording r{{full.time_s.begin(), full.time_s.begin() + rows}, {{full.probes[0].begin(), full.probes[0].begin() + rows}}};
    const Identification id = identify(r);
    print_row(("truncated to " + std::to_string(rows) + " rows").c_str(), f, zeta, id.joint);
    EXPECT_EQ(has(id.verdicts, IdentifyVerdict::too_short), rows < kIdentifyMinSamples) << rows;
    if (rows >= 8) {
      ASSERT_TRUE(id.joint.frequency_hz) << rows;
      EXPECT_NEAR(*id.joint.frequency_hz / f, 1.0, 1e-6) << rows;
    }
  }
  // Under half a cycle of a slow motion: too short even with plenty of rows.
  Recording slow{uniform_times(240.0, 0.2), {}};
  slow.probes.push_back(analytic_at(slow.time_s, 1.0, 0.1, 0.1, 0.0));
  EXPECT_TRUE(has(identify(slow).verdicts, IdentifyVerdict::too_short));
}

TEST(Identify, ClippedMotionIsFlagged) {
  Recording r{uniform_times(60.0, 3.0), {}};
  r.probes.push_back(analytic_at(r.time_s, 2.0, 0.1, 0.1, 0.0));
  for (double& v : r.probes[0]) v = std::max(v, -0.06);  // a joint limit at -0.06
  EXPECT_TRUE(has(identify(r).verdicts, IdentifyVerdict::clipped));
}

// Two probes of one motion in different units share its poles; a flat column does not oscillate.
TEST(Identify, SeveralProbes) {
  const double f = 4.0, zeta = 0.25;
  Recording r{uniform_times(60.0, 3.0), {}};
  r.probes.push_back(analytic_at(r.time_s, f, zeta, 0.02, 1.0));
  r.probes.push_back(analytic_at(r.time_s, f, zeta, -30.0, 90.0));  // an angle in degrees
  const Identification id = identify(r);
  ASSERT_EQ(id.probes.size(), 2u);
  for (const MotionFit& fit : {id.joint, id.probes[0], id.probes[1]}) {
    EXPECT_NEAR(*fit.frequency_hz / f, 1.0, 1e-6);
    EXPECT_NEAR(*fit.damping_ratio, zeta, 1e-6);
  }
  EXPECT_NEAR(id.joint.equilibrium[1], 90.0, 1e-5);
  r.probes.push_back(std::vector<double>(r.time_s.size(), 3.0));
  const Identification flat = identify(r);
  EXPECT_TRUE(has(flat.probes[2].verdicts, IdentifyVerdict::not_oscillating));
  EXPECT_NEAR(*flat.joint.frequency_hz / f, 1.0, 1e-6);
}

TEST(Identify, ValidationNamesRowAndColumn) {
  Recording r{{0.0, 0.1, 0.2, 0.2, 0.4}, {{1, 2, 3, 4, 5}}};
  auto e = validate_recording(r);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->row, 3u);
  EXPECT_EQ(e->column, 0u);
  r.time_s[3] = 0.3;
  r.probes[0][2] = NAN;
  e = validate_recording(r);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->row, 2u);
  EXPECT_EQ(e->column, 1u);
  r.probes[0][2] = 3;
  r.probes.push_back({1, 2});
  e = validate_recording(r);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->column, 2u);
  r.probes.pop_back();
  EXPECT_FALSE(validate_recording(r));
  EXPECT_TRUE(validate_recording(Recording{{0.0}, {{1.0}}}));
  EXPECT_TRUE(validate_recording(Recording{{0.0, 1.0}, {}}));
}

}  // namespace
}  // namespace softtune
